// SPDX-License-Identifier: Apache-2.0
#pragma once
// What flight health follows over a deployment, and the rule that makes a
// change in each an alert a pilot can act on (docs/health.md).
#include <array>
#include <cstddef>
#include <limits>
#include <string>

namespace glider::health {

enum class HealthEffect : int {
  kDragChange = 0,    // ratio to the vehicle file's drag (fouling)
  kBuoyancyOffset,    // g (a leak, a lost or gained weight, a lost wing's volume)
  kPumpRate,          // cc/s while the pump runs (pump ageing)
  kPumpLag,           // s (displaced volume behind the pump's reading; dynamic model only)
  kFinEffectiveness,  // ratio to the vehicle file's yaw per fin angle (a bent or lost fin)
  kRollOffset,        // deg, static roll (a bent or lost wing)
  kBatteryPerKm,      // Ah per km flown through the water
  kCount
};
constexpr std::size_t kHealthEffectCount = static_cast<std::size_t>(HealthEffect::kCount);

// How a change becomes an alert: the shape of the effect over the segments
// (trend.hpp: a significant step or line) and a size threshold on it.
struct AlertRule {
  double step_size = 0.0;  // |step| at least this (unit; a fraction of the level before when relative)
  bool relative = false;
  double rate_per_day = 0.0;      // a line: |slope| at least this (unit/day); 0: steps only
  double min_line_span_days = 0;  // a line is judged only over at least this span
};

struct HealthEffectInfo {
  const char* id;
  const char* unit;
  const char* what;   // one phrase: what the value is
  const char* check;  // what a pilot would check when it alerts
  AlertRule rule;
};

const HealthEffectInfo& info(HealthEffect effect);
HealthEffect health_effect(std::size_t index);

// One segment's value of an effect with its 95 % interval; NaN with `why`
// when the segment cannot judge it.
struct EffectValue {
  double value = std::numeric_limits<double>::quiet_NaN();
  double low = std::numeric_limits<double>::quiet_NaN();
  double high = std::numeric_limits<double>::quiet_NaN();
  std::string why;
  // The value's shift under a bias every segment of the deployment shares (1
  // sigma, signed; the Reynolds prior's: diagnose's Finding::reynolds_prior_shift,
  // 0 where none was flown). Already in this segment's interval; the
  // deployment's levels add it as a common-mode term (assess.cpp).
  double shared_shift = 0.0;
  bool judged() const { return value == value; }
};
using EffectValues = std::array<EffectValue, kHealthEffectCount>;

}  // namespace glider::health
