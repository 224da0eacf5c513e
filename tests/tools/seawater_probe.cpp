// SPDX-License-Identifier: Apache-2.0
// seawater_probe: the C++ seawater chain as a filter, for
// check_seawater_vs_gsw.py to compare with python3-gsw.
// Reads lines "C T P" (conductivity [S/m], in-situ temperature [degC],
// sea pressure [dbar]) and prints "SP SA CT rho C" for each, at full
// precision ("nan" where the C++ functions say the input is out of range);
// C [S/m] is conductivity_from_practical_salinity() of the SP printed.
#include <cstdio>

#include "glider/model/seawater.hpp"

int main() {
  namespace sw = glider::model::seawater;
  double c_s_m = 0.0, t_c = 0.0, p_dbar = 0.0;
  while (std::scanf("%lf %lf %lf", &c_s_m, &t_c, &p_dbar) == 3) {
    const double sp = sw::practical_salinity(c_s_m, t_c, p_dbar);
    const double sa = sw::absolute_salinity(sp);
    const double ct = sw::conservative_temperature(sa, t_c, p_dbar);
    const double rho = sw::density(sa, ct, p_dbar);
    const double c_back = sw::conductivity_from_practical_salinity(sp, t_c, p_dbar);
    std::printf("%.17g %.17g %.17g %.17g %.17g\n", sp, sa, ct, rho, c_back);
  }
  return 0;
}
