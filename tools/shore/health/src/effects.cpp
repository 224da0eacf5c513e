// SPDX-License-Identifier: Apache-2.0
#include "glider/health/effects.hpp"

namespace glider::health {
namespace {

// Thresholds: the smallest change that matters to a pilot (docs/health.md,
// "Alerts"), not fitted to any data set.
const std::array<HealthEffectInfo, kHealthEffectCount> kInfo{{
    {"drag_change",
     "ratio",
     "drag against the vehicle file's",
     "hull fouling (barnacles, weed), a snagged line or bag, a damaged fairing: look at the speed through the "
     "water and the glide angle; plan a recovery or cleaning",
     {0.05, false, 0.01, 1.0}},
    {"buoyancy_offset",
     "g",
     "net buoyancy offset at zero pumped volume",
     "a leak (m_leakdetect, m_vacuum), a lost or gained weight, a lost wing or fin (its volume), a fouled or "
     "damaged oil bladder: compare the ballast needed for neutral at the surface",
     {20.0, false, 0.0, 0.0}},
    {"pump_rate",
     "cc/s",
     "buoyancy pump rate while it runs",
     "pump motor current and battery voltage (m_battery), oil level and air in the oil, hoses; the pump's time to "
     "full (m_ballast_pumped against c_ballast_pumped)",
     {0.15, true, 0.0, 0.0}},
    {"pump_lag",
     "s",
     "lag of the displaced volume behind the pump's reading",
     "air in the oil, a bladder that does not fill freely: the depth rate after each inflection",
     {15.0, false, 0.0, 0.0}},
    {"fin_effectiveness",
     "ratio",
     "yaw rate per fin angle and speed against the vehicle file's",
     "a bent, loose or lost fin (rudder), the fin servo's position (m_fin against c_fin): look at the heading "
     "error and the fin's travel",
     {0.25, true, 0.0, 0.0}},
    {"roll_offset",
     "deg",
     "static roll (logged roll + the roll the yaw shows)",
     "a bent or lost wing, a shifted roll mass: the heading's steady fin offset and m_roll",
     {3.0, false, 0.0, 0.0}},
    {"battery_per_km",
     "Ah/km",
     "charge used per km flown through the water",
     "the energy per km rises with drag (fouling) and with pump work: the coulomb counter (m_coulomb_amphr_total) "
     "and the mission's remaining range",
     {0.25, true, 0.0, 0.0}},
}};

}  // namespace

const HealthEffectInfo& info(HealthEffect effect) { return kInfo[static_cast<std::size_t>(effect)]; }
HealthEffect health_effect(std::size_t index) { return static_cast<HealthEffect>(index); }

}  // namespace glider::health
