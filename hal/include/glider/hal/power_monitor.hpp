// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "glider/hal/time.hpp"

namespace glider::hal {

// Main battery state, as Slocum logs it (m_battery, m_coulomb_amphr_total).
struct PowerSample {
  double battery_voltage_v = 0.0;
  double charge_used_amphr = 0.0;  // since the battery pack was fitted
  Micros time_us = 0;
  bool valid = false;
};

class PowerMonitor {
 public:
  virtual ~PowerMonitor() = default;
  virtual PowerSample read() = 0;
};

}  // namespace glider::hal
