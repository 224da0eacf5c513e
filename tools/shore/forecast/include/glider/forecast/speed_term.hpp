// SPDX-License-Identifier: Apache-2.0
#pragma once
// The forecast's speed term (docs/forecast.md, "The speed through the
// water"): the glider's dead-reckoned speed through the water against the
// model's, the glider's pitch sensor calibration read from the pitch it
// sent home, and (--speed-correction) the model's drag scaled until the two
// speeds agree.
//
// Why the pitch: a Slocum dead-reckons its horizontal speed as depth rate /
// tan(pitch + alpha); a sensor that reads the pitch high counts too little
// speed (comet's m_pitch reads ~1/0.86 of the hull's: ~15 % less speed), and
// matching the model's drag to that speed slows the model for a sensor's
// sake. With the battery fixed (the comet's nsb3 missions) the hull's pitch
// is the trim's, which the model flies; the steady glides' logged pitch over
// the model's is the sensor's scale.
#include <filesystem>
#include <functional>
#include <vector>

#include "glider/firmware/dead_reckoning.hpp"
#include "glider/forecast/forecast.hpp"
#include "glider/forecast/glide_pitch.hpp"
#include "glider/forecast/surfacing_history.hpp"

namespace glider::forecast {

// The glider's pitch sensor calibration, as glider-diagnose's
// --pitch-scale takes it: hull pitch = scale x m_pitch (dives and climbs
// apart; `scale` their mean by samples), with a 1-sigma.
struct PitchCalibrationEstimate {
  bool have = false;
  double dive_scale = 1.0, climb_scale = 1.0;
  double scale = 1.0, scale_sigma = 0.0;
  int glider_samples = 0;
};
// The floor of its sigma: the model's own trim (its pitch moves ~0.2 deg for
// the runs' +-10 g of buoyancy), not read from the data.
inline constexpr double kPitchScaleSigmaFloor = 0.01;
// Scales outside these are not a sensor's calibration (glider-diagnose's
// PitchCalibration allows 0.5-2; a steady glide's pitch off by more than a
// third is another trim, not a sensor).
inline constexpr double kPitchScaleMin = 0.67, kPitchScaleMax = 1.5;

// From the glider's steady glides (its m_pitch) and the model's (the same
// rule on its still-water flight). Without both (fewer than 20 samples of
// either in one direction): have = false, scale 1. The sigma: the dive and
// climb scales' half-difference (a sensor's scale is one number), the
// samples' own spread (one independent sample a minute of 4 s samples), and
// the floor, in quadrature.
PitchCalibrationEstimate estimate_pitch_calibration(const GlidePitch& glider, const GlidePitch& model);

// The factor the glider's dead-reckoned speed is low by (true / counted),
// for its firmware's dead reckoning `dr` at the glider's mean logged pitch of
// each direction, weighted by their samples; and its 1-sigma from the
// scale's. 1 and 0 without an estimate.
struct DrSpeedCalibration {
  double factor = 1.0, sigma = 0.0;
};
DrSpeedCalibration dr_speed_calibration(const fw::DeadReckoningConfig& dr, const GlidePitch& glider,
                                        const PitchCalibrationEstimate& calibration);

// A SIL truth's dead reckoning as a pitch sensor that reads `sensor_scale`
// times the hull's pitch would make it (the benchmark's
// --truth-pitch-bias): a flight-model table whose glide path at pitch p is
// the given one's at sensor_scale x p, so horizontal_speed(p, w) equals the
// given config's horizontal_speed(sensor_scale p, w) inside the table.
fw::DeadReckoningConfig biased_pitch_dead_reckoning(const fw::DeadReckoningConfig& dr, double sensor_scale);

// The steady glides in the glider's files sent home since `since_utc_s`:
// GLIDER_DIR/from-glider/*.csv (glider-convert's conversions of the .sbd /
// .dbd, m_present_time, m_depth, m_pitch; 4 s or coarser), depth rate and
// pitch rate by differences over samples at most 30 s apart. A file whose
// header has no m_depth or m_pitch (science data) is passed over; one that
// names them but is not a readable log is skipped and named in `notes`.
GlidePitch logged_glide_pitch(const std::filesystem::path& glider_dir, double since_utc_s,
                              std::vector<std::string>& notes, int& files);

// The drag factor whose still-water flight glides at `target_m_s`, from the
// nominal flight `at_one`: secant steps on log speed against log drag, the
// first at drag^-1/2, at most x1.3 a step, six flights at most, within
// x0.5-2.5, the best kept (the flights' speed is smooth in drag only to a
// few per cent, where each yo ends), until within 1 %. `fly(factor)` flies
// one (speed 0: no glide there).
struct SpeedFlight {
  double speed_m_s = 0.0;    // DR distance through the water / time
  double average_m_s = 0.0;  // the navigator's mean glide speed then
};
struct SpeedMatch {
  double factor = 1.0;  // 1: none better than the nominal
  double ratio = 1.0;   // target / the best flight's speed
  SpeedFlight flight;   // the best
  double slope = -0.5;  // d log speed / d log drag, the last secant's
  int flights = 0;
};
inline constexpr double kSpeedDragMin = 0.5, kSpeedDragMax = 2.5;  // beyond: a wrong trim, not drag
SpeedMatch match_speed(double target_m_s, const SpeedFlight& at_one, const std::function<SpeedFlight(double)>& fly);

// The speed term of make_forecast: measures the glider's speed (notes, JSON
// current.glider_speed_ratio, pitch_scale, ...), scales setup.vehicle's
// drag when the options say so (forecast.hpp), and seeds the runs' mean
// glide speed.
void measure_speed(const std::vector<Surfacing>& history, const std::filesystem::path& glider_dir, FlightSetup& setup,
                   const ForecastOptions& options, Forecast& f);

}  // namespace glider::forecast
