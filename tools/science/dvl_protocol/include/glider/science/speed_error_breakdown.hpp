// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where two flight models' held-out speed error comes from (issue 26 item 6):
// the squared error of each model against a measured speed through water
// (a DVL's) split by phase (near-surface, leaving and approaching an
// inflection, steady dive, steady climb), by depth, by the error's sign and
// size, and against the angle of attack the measurement implies. The same
// samples for both models, so a part where one model loses to the other is
// read off one table (glider-dvl-protocol prints it).
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace glider::science {

// One scored sample; index 0 and 1 of the arrays are the two models.
struct ScoredSpeedSample {
  double time_s = 0.0, depth_m = 0.0;
  int yo = 0;
  double measured_m_s = 0.0;                     // the reference's speed through water
  std::array<double, 2> model_m_s{};             // each model's speed
  double pitch_rad = 0.0;                        // as both models flew it (+ nose up)
  double depth_rate_measured_m_s = 0.0;          // + down
  std::array<double, 2> depth_rate_model_m_s{};  // each model's, + down
};

// A part of the samples and each model's error there (model - measured).
struct BreakdownRow {
  std::string part;
  std::array<std::size_t, 2> samples{};  // per model: the sign and size rows differ between the two
  std::array<double, 2> rms_m_s{}, mean_m_s{};
  std::array<double, 2> share{};  // of the model's squared error over all used samples
  // Mean angle of attack (deg, > 0 on a normal glide either way): implied by
  // the measured speed and depth rate (asin(w / U) - |pitch|), and each model's.
  double alpha_measured_deg = 0.0;
  std::array<double, 2> alpha_model_deg{};
};

// Samples nearer than this to the first or last sample of their yo's dive
// (or climb) are "at an inflection"; shallower than near_surface_m "near-surface".
struct BreakdownOptions {
  double inflection_s = 60.0;
  double near_surface_m = 15.0;
  double depth_bin_m = 10.0;
};

// The angle of attack (deg) a speed through water and a depth rate imply
// along a pitch: the glide path's angle less the pitch's, as magnitudes; NaN
// where no path has them (speed <= 0, |w| > U).
double implied_alpha_deg(double speed_m_s, double depth_rate_m_s, double pitch_rad);

// Below this implied angle of attack (deg) a measured speed is one no
// flight model with lift can fly at the measured depth rate and pitch.
constexpr double kNoLiftAlphaDeg = 1.0;

// The rows, in groups: "all", "yo means removed" (the within-yo structure),
// phase, depth, sign, size (error within 1, 1-3, beyond 3 cm/s), angle of attack
// implied by the measurement (< 1, 1-2, 2-3, 3-4, >= 4 deg). Only samples
// with use[i] true and every value finite count; groups of one model's own
// split (sign, size) count that model's samples. A part with no sample is
// left out.
std::vector<BreakdownRow> speed_error_breakdown(const std::vector<ScoredSpeedSample>& samples,
                                                const std::vector<bool>& use, const BreakdownOptions& options = {});

}  // namespace glider::science
