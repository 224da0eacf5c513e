// SPDX-License-Identifier: Apache-2.0
#pragma once
// A first-order lag y' = (u - y) / tau, advanced exactly over an interval in
// which the input moves linearly (a rate-limited servo, or a log linearly
// interpolated between samples). Used for the pump lag (paper 003: the
// displaced volume follows the pump's position with a time constant) by the
// simulator and by the diagnosis, so that both lag the same way.
#include <cmath>

namespace glider::model {

// y after `h` seconds, from y0, with the input going linearly from u0 to u1.
// tau <= 0: no lag (y follows u).
inline double first_order_lag_after(double y0, double u0, double u1, double h, double tau) {
  if (!(tau > 0.0)) return u1;
  if (!(h > 0.0)) return y0;
  const double slope_tau = (u1 - u0) / h * tau;
  // Past 700 time constants the decay is below 1e-304: 0, without exp's
  // slow underflow path (8 % of a health update's CPU with a lag near 0).
  const double decay = h > 700.0 * tau ? 0.0 : std::exp(-h / tau);
  return u1 - slope_tau + (y0 - u0 + slope_tau) * decay;
}

}  // namespace glider::model
