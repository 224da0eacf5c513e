// SPDX-License-Identifier: Apache-2.0
#pragma once
// Closing the heading plane's science loop with SIL: a real log's heading
// loop as glider-diagnose identifies it (the extended vehicle and the
// autopilot actually flown) is flown on the heading-hold mission, and its
// heading is measured with the same metric as the real log's; then the
// compensated law on the same vehicle shows what it would have gained.
#include <cstdint>
#include <string>

#include "glider/diagnose/heading_diagnose.hpp"
#include "glider/model/simulator.hpp"
#include "heading_metrics.hpp"

namespace glider::heading_study {

struct GlideSpeeds {
  double dive = 0.0, climb = 0.0;  // m/s through the water, medians
};

struct Replay {
  diagnose::HeadingDiagnosis identified;
  HeadingMetrics real, sil_identified, sil_compensated;
  double loop_delay_s = 0.0;  // placed at the fin in SIL
  // The random yaw flown, calibrated so that the SIL log leaves as much yaw
  // rate unexplained as the real one (never on the heading swing itself).
  double yaw_disturbance_rad_s = 0.0, yaw_disturbance_correlation_s = 0.0;
  // Speed through the water on the glides (the heading track's estimate):
  // the log's, the nominal vehicle's in SIL, and the replay's; with
  // match_speed its lift and drag are scaled by area_scale and its buoyancy
  // offset moved by buoyancy_offset_kg to fly the log's.
  GlideSpeeds log_speed, nominal_speed, sil_speed;
  double area_scale = 1.0, buoyancy_offset_kg = 0.0;
};

// How the replay flies (the defaults are the replay sil.SilHeadingReplay
// checks; switching one off measures what it contributes,
// docs/heading-control.md "Why the replay missed the swing").
struct ReplayOptions {
  // Scale lift and drag and offset the buoyancy so the SIL glides at the
  // log's speeds through the water, diving and climbing (the nominal vehicle
  // flies the heading-hold mission ~60 % faster than the comet logs, and the
  // fin's yaw authority is V fin_gain).
  bool match_speed = true;
  // The calibrated random yaw (vehicle keys heading.yaw_disturbance_*);
  // false: the identified loop alone, with the compass noise.
  bool yaw_disturbance = true;
  // The current's vertical shear across the heading the diagnosis
  // identified (heading_shear.hpp), flown as an east current profile.
  bool current_shear = true;
  // The water (the current's shear across the heading) identified on this
  // other log instead of the replayed one: the glider and its autopilot from
  // one log flown in another log's water (tests/science_real). Empty: the
  // replayed log's own.
  std::string water_log;
  std::uint64_t seed = 1;                                             // the SIL runs' (compass noise, random yaw)
  double integration_step_s = model::GliderSimulator::kDefaultStepS;  // the plant's step (s): the SIL's
};

// `source`: the repository root (boards/); `nominal_vehicle`: the vehicle
// file the diagnosis starts from; the SIL logs go to out_dir. Throws
// diagnose::HeadingUnavailable or std::runtime_error (a flight that fails).
Replay replay_log(const std::string& source, const std::string& log_path, const std::string& nominal_vehicle,
                  const std::string& out_dir, const ReplayOptions& options = {});

}  // namespace glider::heading_study
