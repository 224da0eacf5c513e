// SPDX-License-Identifier: Apache-2.0
#pragma once
// Under-water position the Slocum way (paper 000): the horizontal speed
// through the water from the depth rate and the pitch, with an angle of
// attack either assumed constant (Slocum) or looked up in a table of the
// identified flight model's steady glides (kFlightModel, built at init time
// by the tool that loads the mission: model::steady_glide_for_pitch), along
// the compass heading, plus the depth-averaged current estimated at the
// last surfacing.
#include <array>
#include <cstdint>

#include "glider/firmware/geo.hpp"

namespace glider::fw {

enum class DrMethod : std::int32_t { kAssumedAlpha = 0, kFlightModel = 1 };

struct DeadReckoningConfig {
  static constexpr std::size_t kTableSize = 61;
  DrMethod method = DrMethod::kAssumedAlpha;
  double assumed_alpha_rad = 0.0524;  // 3 deg: gliderflight's median on comet (data/real README)
  // kFlightModel: |alpha| of the steady glide at |pitch| = table_first_pitch
  // + i step, one table for dives and one for climbs (a trim offset makes
  // them differ). Outside the table: the nearest entry.
  double table_first_pitch_rad = 0.1745;  // 10 deg
  double table_step_rad = 0.01745;        // 1 deg
  std::array<double, kTableSize> dive_alpha_rad{};
  std::array<double, kTableSize> climb_alpha_rad{};
  // Shallower than this the glider is inflecting or at the surface: no
  // through-water speed is inferred (the depth rate says nothing about it).
  double min_pitch_rad = 0.1745;  // 10 deg
  double max_speed_m_s = 1.0;     // a depth-rate spike never becomes a sprint
  // kFlightModel: through an inflection (|pitch| < min_pitch_rad) the speed
  // decays from the last glide's with this time constant (from the model).
  double coast_time_constant_s = 30.0;
};

class DeadReckoning {
 public:
  explicit DeadReckoning(const DeadReckoningConfig& config) : config_(config) {}

  void reset(EastNorth position) {
    position_ = position;
    distance_m_ = 0.0;
  }

  // pitch + nose up, depth rate + descending; heading 0 north clockwise;
  // current the estimated depth-averaged water velocity.
  void update(double pitch_rad, double heading_rad, double depth_rate_m_s, EastNorth current_m_s, double dt_s);

  // Horizontal speed through the water the method infers (0 when none).
  double horizontal_speed(double pitch_rad, double depth_rate_m_s) const;
  double alpha_for(double pitch_rad) const;

  EastNorth position() const { return position_; }
  double distance_through_water_m() const { return distance_m_; }
  double last_speed_m_s() const { return speed_; }

 private:
  DeadReckoningConfig config_;
  EastNorth position_{};
  double distance_m_ = 0.0;
  double speed_ = 0.0;
};

}  // namespace glider::fw
