// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "glider/hal/log_record.hpp"

namespace glider::sil {

struct GlideStats {
  std::uint64_t samples = 0;
  double pitch_sum_rad = 0.0;
  double depth_rate_sum_m_s = 0.0;
  double max_pitch_error_rad = 0.0;       // |m_pitch - c_pitch| on settled samples
  std::uint64_t pitch_error_samples = 0;  // settled samples with a pitch target
  double pitch_error_sq_sum_rad2 = 0.0;
  // Settled samples by pitch, whole degrees -90..90 (index + 90): where the
  // glides were, for checks that need more than the mean (glide_check.hpp).
  std::array<std::uint64_t, 181> pitch_histogram_deg{};
  double mean_pitch_rad() const { return samples ? pitch_sum_rad / static_cast<double>(samples) : 0.0; }
  double mean_depth_rate_m_s() const { return samples ? depth_rate_sum_m_s / static_cast<double>(samples) : 0.0; }
  double rms_pitch_error_rad() const {
    return pitch_error_samples ? std::sqrt(pitch_error_sq_sum_rad2 / static_cast<double>(pitch_error_samples)) : 0.0;
  }
};

// The first GPS fix after a segment: how far the dead reckoning was off.
struct SurfacingStats {
  double time_s = 0.0;
  double dr_error_m = 0.0;
  double dr_distance_m = 0.0;  // the segment's DR distance through the water
  double water_vx_m_s = 0.0;   // current estimate after this surfacing
  double water_vy_m_s = 0.0;
};

// What the summary and the SIL tests look at, computed from the log rows as
// they are written. "Settled" = at least settle_s into a dive or climb.
class FlightStats final : public hal::LogSink {
 public:
  explicit FlightStats(double settle_s = 60.0) : settle_s_(settle_s) {}

  bool write(const hal::FlightLogRecord& record) override;

  const GlideStats& dives() const { return dives_; }
  const GlideStats& climbs() const { return climbs_; }
  std::int32_t yos() const { return yos_; }
  // Depth of every inflection: the bottom of each dive, the top of each climb.
  const std::vector<double>& inflection_depths_m() const { return inflections_; }
  double max_depth_m() const { return max_depth_; }
  std::int32_t segments() const { return segments_; }
  std::int32_t waypoints_reached() const { return waypoints_reached_; }
  const std::vector<SurfacingStats>& surfacings() const { return surfacings_; }

 private:
  double settle_s_;
  GlideStats dives_;
  GlideStats climbs_;
  std::int32_t yos_ = 0;
  std::int32_t phase_ = -1;
  hal::Micros phase_start_us_ = 0;
  double extreme_depth_ = 0.0;
  double max_depth_ = 0.0;
  std::vector<double> inflections_;
  std::int32_t segments_ = 0;
  std::int32_t waypoints_reached_ = 0;
  std::vector<SurfacingStats> surfacings_;
};

// Hands every row to two sinks (e.g. the CSV file and the statistics).
class TeeLogSink final : public hal::LogSink {
 public:
  TeeLogSink(hal::LogSink& first, hal::LogSink& second) : first_(first), second_(second) {}
  bool write(const hal::FlightLogRecord& record) override {
    const bool a = first_.write(record);
    const bool b = second_.write(record);
    return a && b;
  }

 private:
  hal::LogSink& first_;
  hal::LogSink& second_;
};

}  // namespace glider::sil
