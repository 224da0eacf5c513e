// SPDX-License-Identifier: Apache-2.0
#pragma once
// The heading plane's vocabulary (docs/diagnose/README.md, "Heading plane"):
// what can make the simulated heading differ from a log's. Three links of
// the loop, each scored on what the log measures of it:
// - the fin servo, c_fin -> m_fin (both logged: measured directly);
// - the vehicle, m_fin -> yaw rate (the heading's slope);
// - the autopilot actually flown, heading error -> c_fin (the log's own
//   commands against the law its header configures).
#include <array>
#include <cstddef>

namespace glider::diagnose {

enum class HeadingEffect : int {
  kFinDelay = 0,       // servo: dead time c_fin -> m_fin (s; nominal: the vehicle file's)
  kFinDeadband,        // servo: a command within this of the fin's position is not followed (rad)
  kYawDelay,           // vehicle: dead time m_fin -> yaw response (compass filter, vehicle) (s)
  kFinEffectiveness,   // vehicle: factor on the yaw rate per fin angle and speed
  kRollOffset,         // vehicle: static roll the log's m_roll does not show (rad)
  kYawTimeConstant,    // vehicle: first-order lag of the yaw rate (s; nominal: the vehicle file's)
  kAutopilotGain,      // autopilot: proportional gain flown (rad of fin per rad of error)
  kAutopilotIntegral,  // autopilot: integral gain flown (rad of fin per rad s)
  kAutopilotDgain,     // autopilot: gain on the heading rate flown (rad of fin per rad/s)
  kAutopilotDelay,     // autopilot: heading reading -> c_fin (the loop's cycle) (s)
  kAutopilotDeadband,  // autopilot: |error| below which (and a rate inside u_heading_rate_deadband) the fin is held
                       // (rad)
  // vehicle: the wings' lift as the roll's turn reads it (ratio; a rival,
  // never selected): the turn scaled by 1/x - at a given lift force a lift
  // slope x times the vehicle file's flies the glide at ~1/x of its angle of
  // attack, and the model turns the roll through that angle. Fitted in a
  // roll offset's place where the two read alike (docs/science.md "A roll
  // offset or the wings' lift").
  kLiftFactor,
  kCount
};
constexpr std::size_t kHeadingEffectCount = static_cast<std::size_t>(HeadingEffect::kCount);

// Which measured signal an effect explains.
enum class HeadingLink { kServo, kVehicle, kAutopilot };

struct HeadingEffectInfo {
  const char* id;
  const char* unit;
  HeadingLink link;
  double scale;  // typical size, for the optimiser's conditioning
  double plausible_min, plausible_max;
  bool magnitude;  // fitted as |x| (a delay or time constant has no sign)
  // Fitted on a grid (plausible_min, + scale, ... plausible_max) with the
  // others fitted at each point, its interval from the profile of the
  // residual: a threshold moves the residual in steps (no gradient).
  bool grid = false;
  // A grid refined around its best point to this step (0: not): where the
  // residual turns sharply at the truth (a servo's deadband replayed free
  // running: docs/science.md "The servo after unlogged cycles").
  double grid_fine_step = 0.0;
  // Never selected: fitted only in a finding's place to judge whether the
  // log tells them apart (select_heading_effects' identifiability).
  bool rival_only = false;
};

const HeadingEffectInfo& info(HeadingEffect effect);
const char* to_string(HeadingLink link);

// Values in the reported units; the nominal ones come from the vehicle file
// and the log's configured autopilot (not constants: see heading_diagnose.hpp).
using HeadingValues = std::array<double, kHeadingEffectCount>;

inline double& at(HeadingValues& v, HeadingEffect e) { return v[static_cast<std::size_t>(e)]; }
inline double at(const HeadingValues& v, HeadingEffect e) { return v[static_cast<std::size_t>(e)]; }

}  // namespace glider::diagnose
