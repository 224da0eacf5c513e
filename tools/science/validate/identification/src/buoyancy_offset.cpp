// SPDX-License-Identifier: Apache-2.0
#include "glider/identification/buoyancy_offset.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>

#include "glider/identification/least_squares.hpp"
#include "glider/model/steady_glide.hpp"
#include "offset_solver.hpp"
#include "propagation.hpp"

namespace glider::identification {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// The symmetric fit (see the header) at one trial offset.
struct Symmetry {
  double delta_rad = 0.0;     // dive minus climb |a| at equal |pitch|
  double delta_se_rad = 0.0;  // NaN without degrees of freedom
  double slope = 0.0;         // d|a|/d|theta| at the mean |pitch|
  int dof = 0;
};

bool is_dive(const SteadyGlideSample& s) { return s.depth_rate_m_s > 0.0; }

std::optional<Symmetry> symmetry_at(const LiftModel& lift, std::span<const SteadyGlideSample> samples,
                                    const BuoyancyOffsetOptions& options, double offset_kg) {
  const auto n = static_cast<Eigen::Index>(samples.size());
  double mean_abs_pitch = 0.0;
  for (const SteadyGlideSample& s : samples) mean_abs_pitch += std::abs(s.pitch_rad);
  mean_abs_pitch /= static_cast<double>(n);
  const bool slope_given = options.alpha_per_pitch.has_value();
  const int trend_terms = slope_given ? 0 : std::clamp(options.trend_degree, 0, 2);
  Eigen::MatrixXd design(n, 2 + trend_terms);
  Eigen::VectorXd abs_alpha(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const SteadyGlideSample& s = samples[static_cast<std::size_t>(i)];
    const auto glide = glide_from_lift(lift, s, offset_kg);
    if (!glide) return std::nullopt;
    const double u = std::abs(s.pitch_rad) - mean_abs_pitch;
    design(i, 0) = is_dive(s) ? 0.5 : -0.5;
    design(i, 1) = 1.0;
    for (int k = 1; k <= trend_terms; ++k) design(i, 1 + k) = std::pow(u, k);
    abs_alpha(i) = std::abs(glide->alpha_rad) - (slope_given ? *options.alpha_per_pitch * u : 0.0);
  }
  const LinearFit fit = least_squares(design, abs_alpha);
  if (!fit.ok) return std::nullopt;
  Symmetry sym;
  sym.delta_rad = fit.coefficients[0];
  sym.delta_se_rad = fit.standard_errors[0];
  sym.slope = slope_given ? *options.alpha_per_pitch : (trend_terms >= 1 ? fit.coefficients[2] : 0.0);
  sym.dof = fit.dof;
  return sym;
}

// Offsets that keep every dive heavy and every climb light (else a glide
// cannot be read), inside the searched range.
std::pair<double, double> feasible_offsets(std::span<const SteadyGlideSample> samples,
                                           const BuoyancyOffsetOptions& options) {
  double lo = options.search_min_kg;
  double hi = options.search_max_kg;
  for (const SteadyGlideSample& s : samples) {
    if (is_dive(s)) {
      lo = std::max(lo, -s.ballast_net_kg + 1e-6);
    } else {
      hi = std::min(hi, -s.ballast_net_kg - 1e-6);
    }
  }
  return {lo, hi};
}

// First sign change of f scanning [lo, hi] in `steps`, then the Illinois
// variant of regula falsi (delta is smooth and monotonic in the offset: a
// few evaluations instead of bisection's forty). Points where f has no
// value are skipped in the scan.
std::optional<double> find_root(const std::function<std::optional<double>(double)>& f, double lo, double hi,
                                int steps) {
  if (!(lo < hi)) return std::nullopt;
  std::optional<double> x_prev;
  double f_prev = 0.0;
  for (int i = 0; i <= steps; ++i) {
    const double x = lo + (hi - lo) * i / steps;
    const auto fx = f(x);
    if (!fx) {
      x_prev.reset();
      continue;
    }
    if (*fx == 0.0) return x;
    if (x_prev && (f_prev < 0.0) != (*fx < 0.0)) {
      double a = *x_prev;
      double fa = f_prev;
      double b = x;
      double fb = *fx;
      for (int k = 0; k < 100 && std::abs(b - a) > 1e-10; ++k) {
        const double c = b - fb * (b - a) / (fb - fa);
        const auto fc = f(c);
        if (!fc) return std::nullopt;
        if (*fc == 0.0) return c;
        if ((*fc < 0.0) == (fb < 0.0)) {
          fa *= 0.5;  // `a` is kept again: halve its weight so that it moves too
        } else {
          a = b;
          fa = fb;
        }
        b = c;
        fb = *fc;
      }
      return b;
    }
    x_prev = x;
    f_prev = *fx;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> detail::solve_offset(const LiftModel& lift, std::span<const SteadyGlideSample> samples,
                                           const BuoyancyOffsetOptions& options, std::optional<double> near_kg) {
  auto delta = [&](double offset) -> std::optional<double> {
    const auto sym = symmetry_at(lift, samples, options, offset);
    return sym ? std::optional<double>(sym->delta_rad) : std::nullopt;
  };
  const auto [lo, hi] = feasible_offsets(samples, options);
  if (near_kg) {
    // A perturbed problem: its root is close to the unperturbed one.
    constexpr double kHalfWidthKg = 0.02;
    const auto root = find_root(delta, std::max(lo, *near_kg - kHalfWidthKg), std::min(hi, *near_kg + kHalfWidthKg), 8);
    if (root) return root;
  }
  return find_root(delta, lo, hi, 100);
}

BuoyancyOffsetEstimate estimate_buoyancy_offset(const LiftModel& lift, std::span<const SteadyGlideSample> samples,
                                                const BuoyancyOffsetOptions& options) {
  BuoyancyOffsetEstimate est;
  for (const SteadyGlideSample& s : samples) (is_dive(s) ? est.dives : est.climbs) += 1;
  if (est.dives == 0 || est.climbs == 0) {
    est.error = "needs steady glides both down and up (dives " + std::to_string(est.dives) + ", climbs " +
                std::to_string(est.climbs) + ")";
    return est;
  }
  const auto offset = detail::solve_offset(lift, samples, options);
  if (!offset) {
    est.error =
        "no offset makes the glides symmetric (too few glides for the trend, or no sign change of the "
        "up/down |alpha| difference within the searched offsets)";
    return est;
  }
  est.ok = true;
  est.offset_kg = *offset;
  const Symmetry sym = *symmetry_at(lift, samples, options, *offset);
  est.alpha_per_pitch = sym.slope;
  est.dof = sym.dof;

  // delta is smooth in the offset: its slope turns se(delta) into kg.
  const double h = 1e-4;
  const auto plus = symmetry_at(lift, samples, options, *offset + h);
  const auto minus = symmetry_at(lift, samples, options, *offset - h);
  const double slope = (plus && minus) ? (plus->delta_rad - minus->delta_rad) / (2.0 * h) : kNan;
  est.residual_se_kg = sym.delta_se_rad / std::abs(slope);
  SampleUncertainty sd = options.input_sd;
  sd.battery_pos_m = 0.0;  // the battery does not enter the force balance
  est.input_se_kg = detail::propagate_sample_errors(samples, sd, 1, [&](std::span<const SteadyGlideSample> perturbed) {
    const auto root = detail::solve_offset(lift, perturbed, options, *offset);
    return root ? std::optional<Eigen::VectorXd>(Eigen::VectorXd::Constant(1, *root)) : std::nullopt;
  })[0];
  est.uncertainty_kg = std::isnan(est.residual_se_kg) ? est.input_se_kg : std::max(est.residual_se_kg, est.input_se_kg);

  for (const SteadyGlideSample& s : samples) est.glides.push_back(*glide_from_lift(lift, s, *offset));

  BuoyancyOffsetOptions pair_options = options;
  pair_options.alpha_per_pitch = est.alpha_per_pitch;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!is_dive(samples[i])) continue;
    for (std::size_t j = 0; j < samples.size(); ++j) {
      if (is_dive(samples[j])) continue;
      const std::array<SteadyGlideSample, 2> pair{samples[i], samples[j]};
      const auto pair_offset = detail::solve_offset(lift, pair, pair_options, *offset);
      est.pairs.push_back({static_cast<int>(i), static_cast<int>(j), pair_offset.value_or(kNan)});
    }
  }
  return est;
}

double polar_alpha_per_pitch(const model::Hydrodynamics& prior, double abs_pitch_rad) {
  // The polar's shape does not depend on the density or the size of m0.
  const double step = 1e-4;
  const auto steeper = model::steady_glide_for_pitch(prior, 1025.0, -(abs_pitch_rad + step), 0.1);
  const auto flatter = model::steady_glide_for_pitch(prior, 1025.0, -(abs_pitch_rad - step), 0.1);
  if (!steeper.glide || !flatter.glide) return kNan;
  return (steeper.glide->alpha_rad - flatter.glide->alpha_rad) / (2.0 * step);
}

}  // namespace glider::identification
