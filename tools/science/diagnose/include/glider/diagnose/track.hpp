// SPDX-License-Identifier: Apache-2.0
#pragma once
// The whole log for the dynamic flight model: every sample, turns and all,
// grouped in continuous runs, with the inputs interpolated between the
// glider's (irregular, 1-5 s) cycles. The steady-glide samples of
// observations.hpp are a subset; this is what the dynamic fit flies through.
#include <cstddef>
#include <span>
#include <vector>

#include "glider/diagnose/pump_ramp.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/flightlog/phases.hpp"

namespace glider::diagnose {

struct Track {
  // One entry per sample of a run (samples outside runs are dropped).
  std::vector<double> time_s, depth_m, depth_rate_m_s, pitch_rad, ballast_cc, battpos_in;
  std::vector<double> pitch_slope_rad_s;  // the pitch between samples is a monotone cubic with these slopes
  // 1 where the log stored the depth at this sample; elsewhere depth_m is the
  // reader's straight line between stored neighbours (a decimated .sbd), and
  // the model's depth is read the same way (read_as_stored) before the rate
  // estimator: a line between 4 s samples of a curved trace is not the trace.
  std::vector<char> depth_stored;
  std::vector<PumpRamp> ballast_ramp;                // the ballast from each sample to the next (pump_ramp.hpp)
  std::vector<double> temperature_c, density_kg_m3;  // NaN where the log has none
  std::vector<double> speed_through_water_m_s;       // measured (a DVL's), NaN where none
  std::vector<flightlog::Phase> phase;
  std::vector<int> yo;                 // a dive and what follows it up to the next dive; -1 before the first
  std::vector<std::size_t> run_first;  // first sample of each run; a run ends where the next begins
  std::vector<std::size_t> scored;     // samples whose depth rate the fit compares (sorted)
  double rate_half_window_s = 0.0, max_gap_s = 0.0;  // how depth_rate_m_s was estimated
  double spin_up_s = 0.0;  // from the start of each run: not scored (the model's start state is fitted there)
  // Median of the logged temperatures (NaN without any): the reference of the
  // thermal_expansion effect (flight_model.hpp's apply).
  double median_temperature_c = 0.0;
  std::size_t size() const { return time_s.size(); }
  std::size_t run_end(std::size_t run) const { return run + 1 < run_first.size() ? run_first[run + 1] : size(); }
};

struct TrackOptions {
  double max_gap_s = 30.0;  // a longer gap (surface dialog, lost data) ends a run
  // Runs stay below this depth: at the surface the measured depth (waves,
  // partial immersion of the 0.2 m hull) says nothing about the buoyancy.
  double run_min_depth_m = 1.0;
  double min_depth_m = 2.0;  // shallower samples are not scored (waves, partial immersion)
  // The measured depth rate is the slope of the depth over +-this (0: a
  // centred difference, as gliderflight's np.gradient).
  double rate_half_window_s = 5.0;
  // The measured pitch (the model's input) is smoothed by a parabola over +-this.
  double pitch_half_window_s = 5.0;
  double spin_up_s = 60.0;  // not scored after a run starts: the model's start state is fitted there
  // Depth and pitch read as the log stored them (docs/science.md, "Decimated
  // depth and pitch"): the pitch a cubic through its stored samples, the
  // model's depth read as the measured one between stored depths. false: the
  // rule before, every row's filled value taken as a measurement (kept to
  // measure the difference: tests/decimation).
  bool as_stored = true;
};

// The depth rate estimator used for the measured depth (and for the
// modelled one, so that the two are compared through the same filter): the
// slope of a straight line fitted to the depth within +-half_window_s (no gap
// longer than max_gap_s inside), else a centred / one-sided difference.
flightlog::Column depth_rate_estimate(std::span<const double> time, std::span<const double> depth, double half_window_s,
                                      double max_gap_s);

// The same at sample i alone, for a depth without gaps in its values (every
// one finite): what a model's flight needs at the few samples it is scored on.
double depth_rate_estimate_at(std::span<const double> time, std::span<const double> depth, std::size_t i,
                              double half_window_s, double max_gap_s);

// The depth as a log that stored it only where `stored` is 1 is read: the
// samples between two stored ones no more than max_gap_s apart become the
// straight line between them (flightlog::interpolate_linear's rule), the
// others are kept. The model's depth goes through this before the rate
// estimator, as the measured depth went through the reader's fill.
void read_as_stored(std::span<const double> time, std::span<const char> stored, std::span<double> depth,
                    double max_gap_s);

// Runs need pitch, ballast and depth; battery, temperature and CTD density
// are used where the log has them. Two optional columns beyond Slocum's:
// sci_water_density (in-situ density, kg/m^3, used instead of computing it
// from the CTD) and sci_speed_through_water (m/s, e.g. a DVL's: never
// fitted, only scored).
Track prepare_track(const flightlog::FlightLog& log, const TrackOptions& options = {});

}  // namespace glider::diagnose
