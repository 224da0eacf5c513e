// SPDX-License-Identifier: Apache-2.0
#pragma once
// One segment measured: every health effect's value in that segment alone,
// so a new surfacing costs one segment's fits, never the deployment's.
// The drag and buoyancy offset (and the pump lag where the data allow the
// dynamic model) come from the diagnosis core (glider::diagnose::diagnose,
// fit_only); the fin effectiveness and roll from its heading plane; the pump
// rate and the charge per km are read off the logged values.
#include <limits>
#include <string>
#include <vector>

#include "glider/health/effects.hpp"
#include "glider/health/segments.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::health {

struct SegmentMeasurement {
  std::string name;
  std::vector<std::string> files;
  std::string fingerprint;
  std::string glider;                 // the name its files carry (empty: none)
  double time_offset_s = 0.0;         // added to the log's clock (SIL logs placed in the deployment)
  double start_s = 0.0, end_s = 0.0;  // deployment time (the log's clock + the offset)
  double time_s = 0.0;                // the middle: where its values sit on the time axis
  bool judged = false;                // the vertical plane could be fitted
  std::string why;                    // not judged: why (names the file)
  EffectValues effects;
  // The fin's spread under water (deg, NaN: no m_fin): the turns that tell
  // the fin's effect on the yaw rate (fin_spread_deg; below kMinFinSpreadDeg
  // the fin is not judged on this segment).
  double fin_spread_deg = std::numeric_limits<double>::quiet_NaN();
  // The heading's spread under water (deg, NaN: no m_heading): the turning
  // the fin's motion made (heading_spread_deg; below kMinHeadingSpreadDeg the
  // fin is not judged on this segment either).
  double heading_spread_deg = std::numeric_limits<double>::quiet_NaN();
  double cost_s = 0.0;  // wall time of the measurement
};

// A segment whose fin moved less than this (its standard deviation under
// water) turned too little to tell the fin's effectiveness: a straight
// transect's fin makes only the loop's small corrections, which the closed
// loop reads weak. Designed on SIL segments (bench_health --transects 3,
// seed 321276411): transects with no turn or one turn of up to 38 deg moved
// the fin 0.52-1.34 deg and read it 0.57-0.83 for 1; the box's turns
// 4.70-5.30 deg, reading 0.997-1.000. The threshold sits between them (their
// geometric middle; docs/health.md, "The fin is judged only on segments
// that turn").
inline constexpr double kMinFinSpreadDeg = 2.5;

// The standard deviation (deg) of the stored m_fin below 2 m: the excitation
// of the yaw rate that the heading fit reads the fin from. NaN with fewer
// than 10 such values or no m_fin.
double fin_spread_deg(const flightlog::FlightLog& log);

// A segment whose heading turned less than this (its circular standard
// deviation under water) is not judged on the fin either, however much the
// fin moved: a fin that chases a random yaw (waves, turbulence) or compass
// noise moves without turning the glider, and the closed loop reads it weak.
// Designed on SIL segments in disturbed water (bench_health --transects N
// --yaw-disturbance 0.3-0.8 --compass-noise 1-1.9, seeds 126609804,
// 392876965, 833719070, 483023233): 128 straight or one-turn transects moved
// the fin 2.97-8.19 deg (past kMinFinSpreadDeg) but turned 2.04-5.99 deg and
// read the fin 0.28-0.45 for 1 (3 false fin alerts in 9 deployments); the box
// turned 158 deg or more. The threshold is 1.7 times the largest straight
// one, far below the box (docs/health.md, "The fin in disturbed water").
inline constexpr double kMinHeadingSpreadDeg = 10.0;

// The circular standard deviation (deg) of m_heading below 2 m: how far the
// segment's heading turned. NaN with fewer than 10 such values or no
// m_heading.
double heading_spread_deg(const flightlog::FlightLog& log);

// Never throws for the data (a segment with no dives, too thin, a vehicle
// that cannot fly it: judged = false and `why`).
SegmentMeasurement measure_segment(const model::VehicleParams& nominal, const LoadedSegment& segment,
                                   double time_offset_s);

// The pump's rate while it runs (cc/s): the mean over the intervals between
// stored m_ballast_pumped values where the pump ran the whole interval (it
// also moved in the intervals before and after), with its Student-t
// interval; NaN and why when there are fewer than 3 such intervals.
EffectValue pump_rate(const flightlog::FlightLog& raw);

// The median spacing (s) of the stored m_depth values: the resolution in
// time of what the vertical plane sees (NaN without two of them).
double depth_sample_spacing_s(const flightlog::FlightLog& log);

// A lag fitted from samples `spacing_s` apart is not known finer than half
// that spacing: its 95 % interval widened to at least +-spacing/2 about the
// value (never below 0, a lag has no sign). The core's Jacobian interval
// claims less: +-0.12 s at 28.7 s for a 30 s lag on 4 s .sbd (health.PumpLag's
// segments, missing the truth by 10 half-widths), [0, 0.006] at 0.
EffectValue lag_at_sampling_resolution(EffectValue lag, double spacing_s);

// Charge per km through the water: the coulomb counter's rise over the
// distance flown in the glides (depth change / tan |pitch|).
EffectValue battery_per_km(const flightlog::FlightLog& log);

}  // namespace glider::health
