// SPDX-License-Identifier: Apache-2.0
#pragma once
// A log flown by gliderflight's own steady model, for the calibration tests:
// three yos between about 30 and 69 m (3-7 bar), 1 s records, each record's
// pressure the one the model's own vertical velocity gives plus a vertical
// water velocity (a fixed point: the buoyancy depends on the pressure it
// produces).
#include "glider/science/gliderflight_model.hpp"

namespace glider::science::test {

inline GliderflightInput flown_by(const GliderflightParameters& truth, double water_w_down_m_s = 0.0) {
  GliderflightInput in;
  for (int k = 0; k < 1800; ++k) {
    const bool dive = (k / 300) % 2 == 0;
    in.time_s.push_back(k);
    in.pitch_rad.push_back(dive ? -0.4 : 0.4);
    in.buoyancy_change_cc.push_back(dive ? -200.0 : 200.0);
    in.density_kg_m3.push_back(1004.0);
    in.pressure_bar.push_back(4.5);
  }
  for (int pass = 0; pass < 20; ++pass) {
    const GliderflightResult r = gliderflight_solve(GliderflightKind::kSteady, truth, in);
    double height_m = -30.0;  // w is + up
    for (std::size_t i = 0; i < in.time_s.size(); ++i) {
      in.pressure_bar[i] = -height_m * truth.rho0_kg_m3 * 9.81 / 1e5;
      height_m += r.w_m_s[i] - water_w_down_m_s;
    }
  }
  return in;
}

}  // namespace glider::science::test
