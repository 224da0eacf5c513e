// SPDX-License-Identifier: Apache-2.0
#pragma once
// The ballast pump between the log's samples, modelled as the actuator it is:
// it holds, then moves at its rate, then holds. A Slocum log keeps a row every
// 2-5 s while a stroke takes 10-20 s, so a straight line between two samples
// starts each stroke early and ends it late (up to half an interval each).
// The diagnosis read that smear as a shorter pump lag (-0.1 s) and a stronger
// lift (+2-3 %) on thinned SIL logs, where the same flights at 1 Hz were
// unbiased (bench_diagnose_coverage --sampling, docs/diagnose/README.md).
#include <cstddef>
#include <span>
#include <vector>

namespace glider::diagnose {

// Over the interval from one sample (value v0) to the next (v1): v0 up to
// fraction `start`, a straight line to v1 at fraction `end`, v1 after.
// {0, 1} is the straight line between the samples.
struct PumpRamp {
  double start = 0.0, end = 1.0;
};

// One ramp per sample (the interval to the next; the last of a run is
// {0, 1}). A stroke is a run of consecutive intervals in which the ballast
// moves the same way (by more than the sensor's ~0.3 cc jitter); its inner
// intervals are flown at full rate, which measures the pump's rate (the
// stroke's own, else the log's median for that direction: filling against the
// pressure is slower than emptying). The first interval of a stroke then ends
// at full rate and starts when that rate needs; the last starts at full rate;
// a stroke inside one interval is centred in it. Without any inner interval in
// the log the rate is unknown and every ramp is the straight line.
std::vector<PumpRamp> pump_ramps(std::span<const double> time_s, std::span<const double> ballast_cc,
                                 std::span<const std::size_t> run_first);

// The ballast at fraction f of an interval.
double ramp_value(double v0, double v1, const PumpRamp& ramp, double f);

// A first-order lag (time constant tau_s) of the ballast, advanced exactly
// from y0 at fraction f0 to fraction f of an interval dt_s long.
double lag_over_ramp(double y0, double v0, double v1, const PumpRamp& ramp, double f0, double f, double dt_s,
                     double tau_s);

}  // namespace glider::diagnose
