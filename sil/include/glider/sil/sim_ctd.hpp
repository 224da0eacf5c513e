// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <cstdint>
#include <limits>

#include "glider/model/simulator.hpp"
#include "glider/sil/portable_random.hpp"
#include "glider/sil/sim_hal.hpp"

namespace glider::sil {

// One CTD record in the Slocum science units; NaN = not sampled.
struct CtdReading {
  double temperature_c = std::numeric_limits<double>::quiet_NaN();     // sci_water_temp
  double conductivity_s_m = std::numeric_limits<double>::quiet_NaN();  // sci_water_cond
  double pressure_bar = std::numeric_limits<double>::quiet_NaN();      // sci_water_pressure (gauge)
};

// The science bay's pumped CTD on the simulated water at the vehicle: the
// water's temperature, the conductivity of its salinity at that temperature
// and pressure (inverse PSS-78), and the sea pressure the water column uses
// (model::sea_pressure_dbar), each with seeded Gaussian noise. So TEOS-10 of
// a reading gives back the density the vehicle felt, to within the noise.
// The firmware never reads it (the CTD is a science sensor, logged only);
// sampling allocates nothing.
class SimCtd {
 public:
  SimCtd(const SensorNoise& noise, std::uint64_t seed) : noise_(noise), random_(seed) {}

  // `powered`: the science bay samples (real logs have no CTD at the
  // surface). A water column without salinity gives no reading either.
  CtdReading sample(const model::Truth& truth, bool powered);

 private:
  SensorNoise noise_;
  PortableRandom random_;
};

}  // namespace glider::sil
