// SPDX-License-Identifier: Apache-2.0
#pragma once
// gliderflight's flight models, written here from their published equations
// (Merckelbach, Berger, Krahmann, Dengler, Carpenter 2019, "A dynamic flight
// model for Slocum gliders and implications for turbulence microstructure
// measurements", JTECH 36, 281-296; the package gliderflight 1.2 by the same
// author, MIT), so that the DVL comparison can fit both tools on the same
// training yos and score both on the same held-out yos (tools/science/
// dvl_protocol, docs/diagnose/README.md). The package itself is not a
// dependency (it is not packaged for Debian): its example fit's published
// figures are what this implementation is checked against
// (science.dvl_protocol.gliderflight_reproduced).
//
// The model: lift L = q (a_w + a_h) alpha, drag D = q (C_D0 + C_D1 alpha^2),
// q = rho S U^2 / 2; buoyancy F_B = g rho (V_g (1 - eps p) + V_bp), weight
// m_g g. Steady: the angle of attack from
//   alpha = (C_D0 + C_D1 alpha^2) / ((a_h + a_w) tan(alpha + pitch)),
// then U^2 = 2 (F_B - F_g) sin(pitch + alpha) / (rho S (C_D0 + C_D1 alpha^2)).
// Dynamic: the horizontal and vertical velocities (u, w) integrated with
// classic RK4 on a uniform time grid, the mass matrix with added masses
// k1 m_g (along the hull) and k2 m_g (across), u = w = 0 at the surface.
// Signs as gliderflight's: w positive up, pitch positive nose up, the depth
// rate dh/dt = -dp/dt / (rho0 g).
#include <cstddef>
#include <vector>

namespace glider::science {

struct GliderflightParameters {
  double cd0 = 0.15;            // parasitic drag coefficient
  double cd1 = 10.5;            // induced drag per rad^2 (gliderflight's example sets it)
  double ah = 3.8;              // hull lift slope (1/rad)
  double aspect_ratio = 7.0;    // wing
  double sweep_rad = 0.750492;  // 43 deg
  double area_m2 = 0.1;         // S
  double epsilon_per_pa = 5e-10;
  double mass_kg = 70.0;             // m_g
  double volume_m3 = 70.0 / 1004.0;  // V_g (the example's)
  double rho0_kg_m3 = 1004.0;        // pressure -> depth, as the example
  double k1 = 0.2, k2 = 0.98;        // added mass fractions (the example's dynamic model)
  double dt_s = 1.0;                 // the dynamic model's step (the example's calibration)
  double surface_m = 0.5;            // shallower than this: u = w = 0
  // The wing's lift slope from its planform (gliderflight's parameterisation).
  double aw() const;
};

// The log's time series, one entry per record (gliderflight works on all of them).
struct GliderflightInput {
  std::vector<double> time_s, pressure_bar, pitch_rad, buoyancy_change_cc, density_kg_m3;
  // A stated vertical water velocity at each record (m/s, + down; empty: none). The glider's depth rate is its
  // flight through the water plus this, so a calibration compares w - water with dh/dt; the speed through
  // the water does not depend on it. The DVL protocol gives gliderflight the profile glider-diagnose fitted,
  // so both models carry the same water term (--shared-water).
  std::vector<double> water_w_down_m_s;
};

struct GliderflightResult {
  std::vector<double> speed_m_s;  // U at each record
  std::vector<double> w_m_s;      // U sin(pitch + alpha): the glider's vertical velocity, + up
  std::vector<double> alpha_rad;
};

enum class GliderflightKind { kSteady, kDynamic };

// dh/dt from the pressure, as np.gradient (centred inside, one-sided at the ends).
std::vector<double> gliderflight_depth_rate(const GliderflightInput& in, double rho0_kg_m3);

GliderflightResult gliderflight_solve(GliderflightKind kind, const GliderflightParameters& p,
                                      const GliderflightInput& in);

// What a calibration fits: gliderflight's example's two, or with its hull
// compressibility epsilon as a third (gliderflight's calibrate takes any of
// its parameters; the protocol gives it the one glider-diagnose may fit).
enum class GliderflightFit { kCd0Mass, kCd0MassEpsilon };

// Calibrates C_D0 and m_g (gliderflight's example: calibrate("Cd0", "mg"))
// on the records where `fit` is true: the least mean square of w - dh/dt
// (Nelder-Mead from p's values, converged tighter than scipy's fmin
// defaults, so the minimum is the model's, not the stopping rule's). It
// stops early where the fit diverged: past 200 iterations per parameter
// (scipy fmin's limit), the best point's model not finite at more than half
// the fitted records (gliderflight_diverged).
// Returns p with those fitted; *rms_m_s (if given) the fit's RMS.
GliderflightParameters gliderflight_calibrate(GliderflightKind kind, GliderflightParameters p,
                                              const GliderflightInput& in, const std::vector<bool>& fit,
                                              double* rms_m_s = nullptr,
                                              GliderflightFit what = GliderflightFit::kCd0Mass);

// Whether a solution diverged on the records `fit` marks: not finite at more
// than half of them (a calibration that ends there has no meaning).
bool gliderflight_diverged(const GliderflightResult& r, const std::vector<bool>& fit);
}  // namespace glider::science
