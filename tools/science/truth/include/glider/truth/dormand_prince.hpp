// SPDX-License-Identifier: Apache-2.0
#pragma once
// Dormand-Prince 5(4) with adaptive steps (Hairer, Norsett & Wanner,
// Solving ODEs I, table 5.2 and eq. 4.11-4.13): the truth's own integrator,
// a different method from the project model's fixed-step RK4.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace glider::truth {

struct StepControl {
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-8;
  double max_step_s = 2.0;
  double min_step_s = 1e-6;
};

struct IntegrationStats {
  std::size_t accepted = 0, rejected = 0;
};

// Integrates y' = f(t, y) from t to t_end in place; `h` carries the step
// size from one call to the next. f(t, y, dydt).
template <std::size_t N, class F>
void integrate(F&& f, double& t, std::array<double, N>& y, double t_end, double& h, const StepControl& c,
               IntegrationStats& stats) {
  using State = std::array<double, N>;
  static constexpr double a21 = 1.0 / 5.0;
  static constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
  static constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
  static constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0, a54 = -212.0 / 729.0;
  static constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0, a64 = 49.0 / 176.0,
                          a65 = -5103.0 / 18656.0;
  static constexpr double b1 = 35.0 / 384.0, b3 = 500.0 / 1113.0, b4 = 125.0 / 192.0, b5 = -2187.0 / 6784.0,
                          b6 = 11.0 / 84.0;
  // The 5th-order solution minus the embedded 4th-order one.
  static constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0, e5 = -17253.0 / 339200.0,
                          e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
  State k1, k2, k3, k4, k5, k6, k7, tmp, next;
  h = std::clamp(h, c.min_step_s, c.max_step_s);
  while (t < t_end) {
    const bool last = t + h >= t_end;
    const double step = last ? t_end - t : h;
    f(t, y, k1);
    for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + step * a21 * k1[i];
    f(t + step / 5.0, tmp, k2);
    for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + step * (a31 * k1[i] + a32 * k2[i]);
    f(t + 3.0 * step / 10.0, tmp, k3);
    for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + step * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
    f(t + 4.0 * step / 5.0, tmp, k4);
    for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + step * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
    f(t + 8.0 * step / 9.0, tmp, k5);
    for (std::size_t i = 0; i < N; ++i)
      tmp[i] = y[i] + step * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
    f(t + step, tmp, k6);
    for (std::size_t i = 0; i < N; ++i)
      next[i] = y[i] + step * (b1 * k1[i] + b3 * k3[i] + b4 * k4[i] + b5 * k5[i] + b6 * k6[i]);
    f(t + step, next, k7);
    double err = 0.0;
    for (std::size_t i = 0; i < N; ++i) {
      const double e = step * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
      const double scale = c.absolute_tolerance + c.relative_tolerance * std::max(std::abs(y[i]), std::abs(next[i]));
      err = std::max(err, std::abs(e) / scale);
    }
    if (!std::isfinite(err)) throw std::runtime_error("truth integrator: the state is not finite");
    const double factor = err == 0.0 ? 5.0 : std::clamp(0.9 * std::pow(err, -0.2), 0.2, 5.0);
    if (err <= 1.0) {
      t = last ? t_end : t + step;
      y = next;
      ++stats.accepted;
      if (!last) h = std::min(c.max_step_s, step * factor);
    } else {
      ++stats.rejected;
      h = step * factor;
      if (h < c.min_step_s) throw std::runtime_error("truth integrator: step size underflow");
    }
  }
}

}  // namespace glider::truth
