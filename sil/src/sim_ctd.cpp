// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/sim_ctd.hpp"

#include <algorithm>
#include <cmath>

#include "glider/model/environment.hpp"
#include "glider/model/seawater.hpp"

namespace glider::sil {

CtdReading SimCtd::sample(const model::Truth& truth, bool powered) {
  CtdReading r;
  if (!powered || !std::isfinite(truth.water.practical_salinity)) return r;
  const double p_dbar = model::sea_pressure_dbar(std::max(truth.depth_m, 0.0));
  const double t = truth.water.temperature_c;
  const double c = model::seawater::conductivity_from_practical_salinity(truth.water.practical_salinity, t, p_dbar);
  r.temperature_c = t + noise_.ctd_temperature_c * random_.gaussian();
  r.conductivity_s_m = c + noise_.ctd_conductivity_s_m * random_.gaussian();
  r.pressure_bar = 0.1 * p_dbar + noise_.ctd_pressure_bar * random_.gaussian();
  return r;
}

}  // namespace glider::sil
