// SPDX-License-Identifier: Apache-2.0
#pragma once
// Closing the heading plane's science loop with SIL: a real log's heading
// loop as glider-diagnose identifies it (the extended vehicle and the
// autopilot actually flown) is flown on the heading-hold mission, and its
// heading is measured with the same metric as the real log's; then the
// compensated law on the same vehicle shows what it would have gained.
#include <string>

#include "glider/diagnose/heading_diagnose.hpp"
#include "heading_metrics.hpp"

namespace glider::heading_study {

struct Replay {
  diagnose::HeadingDiagnosis identified;
  HeadingMetrics real, sil_identified, sil_compensated;
  double loop_delay_s = 0.0;  // placed at the fin in SIL
  // The random yaw flown, calibrated so that the SIL log leaves as much yaw
  // rate unexplained as the real one (never on the heading swing itself).
  double yaw_disturbance_rad_s = 0.0, yaw_disturbance_correlation_s = 0.0;
  // Speed through the water on the glides (the heading track's estimate):
  // the log's, the nominal vehicle's in SIL, and the replay's after its
  // lift and drag are scaled by area_scale to fly the log's.
  double log_speed_m_s = 0.0, nominal_speed_m_s = 0.0, sil_speed_m_s = 0.0, area_scale = 1.0;
};

// What the replay flies beyond the identified loop (the defaults are the
// replay sil.SilHeadingReplay checks; the others are the measurements of
// docs/heading-control.md, "What the replay still misses").
struct ReplayOptions {
  // Scale lift and drag so the SIL glides at the log's speed through the
  // water (the nominal vehicle flies the heading-hold mission ~60 % faster
  // than the comet logs, and the fin's yaw authority is V fin_gain).
  bool match_speed = false;
  // The calibrated random yaw (vehicle keys heading.yaw_disturbance_*);
  // false: the identified loop alone, with the compass noise.
  bool yaw_disturbance = true;
};

// `source`: the repository root (boards/); `nominal_vehicle`: the vehicle
// file the diagnosis starts from; the SIL logs go to out_dir. Throws
// diagnose::HeadingUnavailable or std::runtime_error (a flight that fails).
Replay replay_log(const std::string& source, const std::string& log_path, const std::string& nominal_vehicle,
                  const std::string& out_dir, const ReplayOptions& options = {});

}  // namespace glider::heading_study
