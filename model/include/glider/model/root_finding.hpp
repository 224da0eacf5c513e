// SPDX-License-Identifier: Apache-2.0
#pragma once
// The model's one-dimensional solvers, on Boost.Math (no hand-written
// bisection or golden-section loops anywhere in model/): TOMS 748 for a root
// in a sign-changing bracket, Brent for the minimum of a unimodal function.
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace glider::model {

// The root of f in [lo, hi] (lo < hi), given f(lo) and f(hi) of opposite
// signs, to about `bits` significant bits (the default: the last bits of a
// double); TOMS 748 needs ~5-10 evaluations where bisection needs 40-50.
// Without a sign change (or with a NaN end) there is no root to find: the end
// nearer to zero is returned, which is where a bisection would have ended; a
// caller for whom that matters checks the bracket first.
template <class F>
double bracketed_root(F&& f, double lo, double hi, double f_lo, double f_hi,
                      int bits = std::numeric_limits<double>::digits - 2) {
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  if (!((f_lo < 0.0) != (f_hi < 0.0)) || !(f_lo == f_lo) || !(f_hi == f_hi)) {
    return (f_hi == f_hi && (f_lo != f_lo || std::abs(f_hi) < std::abs(f_lo))) ? hi : lo;
  }
  std::uintmax_t max_iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(
      f, lo, hi, f_lo, f_hi, boost::math::tools::eps_tolerance<double>(bits), max_iterations);
  return 0.5 * (a + b);
}

template <class F>
double bracketed_root(F&& f, double lo, double hi, int bits = std::numeric_limits<double>::digits - 2) {
  return bracketed_root(f, lo, hi, f(lo), f(hi), bits);
}

// The x in [lo, hi] where the unimodal f is smallest (Brent's method).
template <class F>
double unimodal_minimum(F&& f, double lo, double hi, int bits = std::numeric_limits<double>::digits / 2) {
  std::uintmax_t max_iterations = 200;
  return boost::math::tools::brent_find_minima(f, lo, hi, bits, max_iterations).first;
}

}  // namespace glider::model
