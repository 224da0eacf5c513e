// SPDX-License-Identifier: Apache-2.0
#include "glider/model/steady_glide.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "flow_forces_inline.hpp"
#include "glider/model/hydrodynamics.hpp"
#include "glider/model/root_finding.hpp"
#include "glider/units.hpp"

namespace glider::model {
namespace {

constexpr double kDeg = kRadPerDeg;  // glider/units.hpp

// Angle of zero lift (C_L is increasing through it inside the fit range).
double zero_lift_alpha(const Hydrodynamics& h) {
  return bracketed_root([&](double alpha) { return force_coefficients(h, alpha).lift; }, -h.fit_valid_to_rad,
                        h.fit_valid_to_rad);
}

// Along the flight branch of one direction (+1 descending: lift must point
// up, C_L > 0; -1 climbing: C_L < 0), parametrised by the distance t from
// the zero-lift angle.
struct Branch {
  const Hydrodynamics& h;
  int direction;
  double alpha0;
  // The polar's slopes, once per branch: force_coefficients(h, alpha) works
  // them out at every call, and a diagnosis's steady model solves a glide
  // per sample (the same numbers, so the same bits).
  PolarSlopes slopes = polar_slopes(h);
  double alpha(double t) const { return alpha0 + direction * t; }
  ForceCoefficients coefficients(double alpha_rad) const {
    return detail::force_coefficients(h, slopes, alpha_rad, 1.0);
  }
  // tan(gamma) = D / |L|: +inf at t = 0, falling to the best glide.
  double tan_gamma(double t) const {
    const ForceCoefficients c = coefficients(alpha(t));
    return c.drag / (direction * c.lift);
  }
  // t of the best glide ratio (unimodal on the fit range).
  double t_best() const {
    return unimodal_minimum([this](double t) { return tan_gamma(t); }, 1e-9, h.fit_valid_to_rad);
  }
};

Branch make_branch(const Hydrodynamics& h, int direction) { return Branch{h, direction, zero_lift_alpha(h)}; }

// The glide with angle of attack `alpha` on `branch` and net buoyancy m0.
SteadyGlide glide_at(const Branch& branch, double t, double density, double gravity, double m0) {
  const double alpha = branch.alpha(t);
  const ForceCoefficients c = branch.coefficients(alpha);
  const double gamma = std::atan(branch.tan_gamma(t));
  const double speed =
      std::sqrt(2.0 * std::abs(m0) * gravity / (density * branch.h.reference_area_m2 * std::hypot(c.lift, c.drag)));
  SteadyGlide g;
  g.glide_path_rad = -branch.direction * gamma;
  g.alpha_rad = alpha;
  g.pitch_rad = g.glide_path_rad + alpha;
  g.speed_m_s = speed;
  g.depth_rate_m_s = -speed * std::sin(g.glide_path_rad);
  g.horizontal_speed_m_s = speed * std::cos(g.glide_path_rad);
  g.net_buoyancy_kg = m0;
  return g;
}

// Net pitching moment of the full model in a given steady glide.
double pitch_moment(const GliderDynamics& dyn, const MassInputs& masses, double depth_m, const SteadyGlide& g) {
  const State s = dyn.make_state(depth_m, g.pitch_rad, g.speed_m_s * std::cos(g.alpha_rad),
                                 g.speed_m_s * std::sin(g.alpha_rad), 0.0, masses);
  return dyn.derivative(0.0, s, masses)[kPi2];
}

double net_buoyancy_at_rest(const GliderDynamics& dyn, const MassInputs& masses, double depth_m) {
  return dyn.evaluate(0.0, dyn.make_state(depth_m, 0.0, 0.0, 0.0, 0.0, masses), masses).net_buoyancy_kg;
}

// The polar with the skin friction's Reynolds term frozen at factor f: the
// steady glides below solve the speed-independent polar, and a drag that
// follows the speed (hydrodynamics.hpp) is the fixed point f = factor(V(f)).
Hydrodynamics frozen_at(const Hydrodynamics& h, double factor) {
  Hydrodynamics out = h;
  out.cd0 = h.cd0 * factor;
  out.cd0_reynolds_exponent = 0.0;
  return out;
}

// solve(const Hydrodynamics& frozen, double factor) -> SteadyGlideResult on
// the speed-independent polar frozen_at(h, factor). The fixed point
// f = factor(V(f)) contracts by about n/2 times the zero-lift drag's share;
// secant steps on r(f) = factor(V(f)) - f settle it in 3-5 passes. The
// tolerance is the factor's to 1e-10: the glide's angle of attack is solved
// to ~1e-10 rad, below which the speed is noise.
template <typename Solve>
SteadyGlideResult with_skin_friction(const Hydrodynamics& h, Solve&& solve) {
  if (h.cd0_reynolds_exponent == 0.0) return solve(h, 1.0);
  constexpr int kMaxPasses = 30;
  constexpr double kTolerance = 1e-10;
  double factor = 1.0, previous_factor = 0.0, previous_residual = 0.0;
  SteadyGlideResult result;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    result = solve(frozen_at(h, factor), factor);
    if (!result.glide) return result;
    const double residual = skin_friction_factor(h, result.glide->speed_m_s) - factor;
    if (std::abs(residual) <= kTolerance * factor) return result;
    double next = factor + residual;  // the plain fixed-point step
    if (pass > 0 && residual != previous_residual) {
      const double secant = factor - residual * (factor - previous_factor) / (residual - previous_residual);
      if (secant > 0.0 && std::isfinite(secant)) next = secant;
    }
    previous_factor = factor;
    previous_residual = residual;
    factor = next;
  }
  result.glide.reset();
  result.error = "steady glide: the speed-dependent drag did not settle";
  return result;
}

// hint: where the last pass of the speed's fixed point found the balance
// (0: none). A later pass's polar differs from the last by a drag factor
// near 1 and its balance lies near: a bracket of +-2 % around the hint is
// tried before the walk.
SteadyGlideResult equilibrium_on(const GliderDynamics& dyn, const MassInputs& masses, double depth_m,
                                 const Branch& branch, double density, double gravity, double m0, double& hint) {
  SteadyGlideResult result;
  auto residual = [&](double t) {
    return pitch_moment(dyn, masses, depth_m, glide_at(branch, t, density, gravity, m0));
  };
  const double t_max = branch.t_best();
  if (hint > 0.0) {
    constexpr double kHintBracket = 0.02;
    const double lo = hint * (1.0 - kHintBracket), hi = std::min(hint * (1.0 + kHintBracket), t_max);
    const double r_lo = residual(lo), r_hi = residual(hi);
    if (lo < hi && (r_lo < 0.0) != (r_hi < 0.0)) {
      hint = bracketed_root(residual, lo, hi, r_lo, r_hi);
      result.glide = glide_at(branch, hint, density, gravity, m0);
      return result;
    }
  }
  // Walk along the branch from the zero-lift angle to the best glide ratio;
  // a moment balance there is the glide the vehicle flies. Beyond the best
  // glide (the back side of the polar) the SIL dynamics do not settle: the
  // vehicle stalls, and this solver says so instead of offering that root.
  const int steps = 400;
  double t_prev = 1e-9;
  double r_prev = residual(t_prev);
  for (int i = 1; i <= steps; ++i) {
    const double t = t_max * i / steps;
    const double r = residual(t);
    if ((r_prev < 0.0) != (r < 0.0)) {
      hint = bracketed_root(residual, t_prev, t, r_prev, r);
      result.glide = glide_at(branch, hint, density, gravity, m0);
      return result;
    }
    t_prev = t;
    r_prev = r;
  }
  result.error = "no steady glide: the pitch trim is " +
                 std::string(residual(t_max) > 0.0 ? "too nose-up" : "too nose-down") +
                 " for this ballast (shallower than the best glide of " +
                 std::to_string(std::atan(branch.tan_gamma(t_max)) / kDeg) + " deg: it stalls)";
  return result;
}

}  // namespace

double min_glide_path_deg(const Hydrodynamics& hydro, int direction) {
  const Branch branch = make_branch(hydro, direction > 0 ? 1 : -1);
  return std::atan(branch.tan_gamma(branch.t_best())) / kDeg;
}

SteadyGlideResult steady_glide_for_path(const Hydrodynamics& hydro, double density_kg_m3, double glide_path_deg,
                                        double net_buoyancy_kg, double gravity_m_s2) {
  if (hydro.cd0_reynolds_exponent != 0.0) {
    return with_skin_friction(hydro, [&](const Hydrodynamics& h, double) {
      return steady_glide_for_path(h, density_kg_m3, glide_path_deg, net_buoyancy_kg, gravity_m_s2);
    });
  }
  SteadyGlideResult result;
  if (!(glide_path_deg > 0.0 && glide_path_deg < 90.0)) {
    result.error = "glide path must be between 0 and 90 deg (magnitude)";
    return result;
  }
  if (net_buoyancy_kg == 0.0 || !std::isfinite(net_buoyancy_kg)) {
    result.error = "a steady glide needs a non-zero net buoyancy";
    return result;
  }
  const Branch branch = make_branch(hydro, net_buoyancy_kg > 0.0 ? 1 : -1);
  const double t_best = branch.t_best();
  const double gamma_min = std::atan(branch.tan_gamma(t_best)) / kDeg;
  if (glide_path_deg < gamma_min) {
    result.error = "glide path shallower than the vehicle's best glide (" + std::to_string(gamma_min) + " deg)";
    return result;
  }
  // On (0, t_best] tan(gamma) falls monotonically from +inf: one root.
  const double target = std::tan(glide_path_deg * kDeg);
  const double t = bracketed_root([&](double s) { return branch.tan_gamma(s) - target; }, 1e-12, t_best);
  result.glide = glide_at(branch, t, density_kg_m3, gravity_m_s2, net_buoyancy_kg);
  return result;
}

PitchGlideSolver::PitchGlideSolver(const Hydrodynamics& hydro)
    : hydro_(hydro), alpha0_(zero_lift_alpha(hydro)), t_best_{}, t_best_low_{} {
  t_best_[0] = Branch{hydro_, 1, alpha0_}.t_best();
  t_best_[1] = Branch{hydro_, -1, alpha0_}.t_best();
  if (hydro_.cd0_reynolds_exponent != 0.0) low_factor_ = skin_friction_factor(hydro_, kBracketSpeedMS);
}

SteadyGlideResult PitchGlideSolver::solve(double density_kg_m3, double pitch_rad, double net_buoyancy_kg,
                                          double gravity_m_s2) const {
  SteadyGlideResult result;
  if (net_buoyancy_kg == 0.0 || !std::isfinite(net_buoyancy_kg) || !std::isfinite(pitch_rad)) {
    result.error = "a steady glide needs a finite pitch and a non-zero net buoyancy";
    return result;
  }
  const int direction = net_buoyancy_kg > 0.0 ? 1 : -1;
  if (hydro_.cd0_reynolds_exponent == 0.0) {
    return solve_on(hydro_, t_best_[direction > 0 ? 0 : 1], density_kg_m3, pitch_rad, net_buoyancy_kg, gravity_m_s2);
  }
  // The zero-lift angle is the lift's alone; the best glide moves to larger
  // angles as the drag grows (at the best glide D'L = DL': more D, and the
  // ratio still falls). So (0, t_best(f_low)] is on the monotone part of
  // every polar with f >= f_low: one bracket for the passes, and the best
  // glide of the pass's own polar only where the pitch lies beyond it.
  const int side = direction > 0 ? 0 : 1;
  return with_skin_friction(hydro_, [&](const Hydrodynamics& h, double factor) {
    if (factor >= low_factor_) {
      // Found on first need: a solver asked once (steady_glide_for_pitch) finds one.
      if (!(t_best_low_[side] > 0.0)) {
        t_best_low_[side] = Branch{frozen_at(hydro_, low_factor_), direction, alpha0_}.t_best();
      }
      SteadyGlideResult within =
          solve_on(h, t_best_low_[side], density_kg_m3, pitch_rad, net_buoyancy_kg, gravity_m_s2);
      if (within.glide) return within;
    }
    return solve_on(h, Branch{h, direction, alpha0_}.t_best(), density_kg_m3, pitch_rad, net_buoyancy_kg, gravity_m_s2);
  });
}

SteadyGlideResult PitchGlideSolver::solve_on(const Hydrodynamics& hydro, double t_best, double density_kg_m3,
                                             double pitch_rad, double net_buoyancy_kg, double gravity_m_s2) const {
  SteadyGlideResult result;
  const int direction = net_buoyancy_kg > 0.0 ? 1 : -1;
  const Branch branch{hydro, direction, alpha0_};
  // Along the branch, |pitch| = gamma - direction * alpha falls from 90 deg
  // at zero lift to its smallest value at the best glide: one root.
  const double target = -direction * pitch_rad;  // pitch magnitude in the glide's direction
  auto pitch_magnitude = [&](double t) { return std::atan(branch.tan_gamma(t)) - direction * branch.alpha(t); };
  const double f_lo = pitch_magnitude(1e-12) - target;
  const double f_hi = pitch_magnitude(t_best) - target;
  if (!(f_lo > 0.0) || !(f_hi < 0.0)) {
    result.error = "pitch outside the steady glides of this buoyancy";
    return result;
  }
  // alpha to ~1e-10 rad (34 bits), as the bisection this replaced.
  const double t = bracketed_root([&](double s) { return pitch_magnitude(s) - target; }, 1e-12, t_best, f_lo, f_hi, 34);
  result.glide = glide_at(branch, t, density_kg_m3, gravity_m_s2, net_buoyancy_kg);
  return result;
}

SteadyGlideResult steady_glide_for_pitch(const Hydrodynamics& hydro, double density_kg_m3, double pitch_rad,
                                         double net_buoyancy_kg, double gravity_m_s2) {
  return PitchGlideSolver(hydro).solve(density_kg_m3, pitch_rad, net_buoyancy_kg, gravity_m_s2);
}

SteadyGlideResult solve_equilibrium(const GliderDynamics& dyn, const MassInputs& masses, double depth_m) {
  SteadyGlideResult result;
  const double m0 = net_buoyancy_at_rest(dyn, masses, depth_m);
  if (std::abs(m0) < 1e-6) {
    result.error = "neutrally buoyant: no steady glide (it hovers)";
    return result;
  }
  const double density = dyn.environment().water.at(depth_m, 0.0).density_kg_m3;
  const double gravity = dyn.environment().gravity_m_s2;
  // The branch's polar at the pass's drag factor; the moment is the full
  // model's (its drag at the glide's own speed: the same at the fixed point).
  double hint = 0.0;
  return with_skin_friction(dyn.vehicle().hydro, [&](const Hydrodynamics& h, double) {
    return equilibrium_on(dyn, masses, depth_m, make_branch(h, m0 > 0.0 ? 1 : -1), density, gravity, m0, hint);
  });
}

double battery_for_glide(const GliderDynamics& dyn, const SteadyGlide& glide, MassInputs masses, double depth_m) {
  const double probe = 0.01;
  masses.battery_pos_m = 0.0;
  const double r0 = pitch_moment(dyn, masses, depth_m, glide);
  masses.battery_pos_m = probe;
  const double r1 = pitch_moment(dyn, masses, depth_m, glide);
  return -r0 * probe / (r1 - r0);
}

TrimResult solve_trim(const GliderDynamics& dyn, double glide_path_deg, double net_buoyancy_kg, double depth_m) {
  TrimResult result;
  const double density = dyn.environment().water.at(depth_m, 0.0).density_kg_m3;
  const SteadyGlideResult steady = steady_glide_for_path(dyn.vehicle().hydro, density, glide_path_deg, net_buoyancy_kg,
                                                         dyn.environment().gravity_m_s2);
  if (!steady.glide) {
    result.error = steady.error;
    return result;
  }
  Trim trim;
  trim.glide = *steady.glide;
  // Net buoyancy is affine in the pumped volume (ballast mass = -rho V).
  const double m0_zero = net_buoyancy_at_rest(dyn, MassInputs{}, depth_m);
  trim.pumped_volume_m3 = (m0_zero - net_buoyancy_kg) / density;
  MassInputs masses{};
  masses.pumped_volume_m3 = trim.pumped_volume_m3;
  trim.battery_pos_m = battery_for_glide(dyn, trim.glide, masses, depth_m);

  const VehicleParams& v = dyn.vehicle();
  trim.within_limits = true;
  if (trim.pumped_volume_m3 < v.ballast.volume_min_m3 || trim.pumped_volume_m3 > v.ballast.volume_max_m3) {
    trim.within_limits = false;
    trim.note = "ballast outside the pump's range";
  } else if (trim.battery_pos_m < v.battery.travel_min_m || trim.battery_pos_m > v.battery.travel_max_m) {
    trim.within_limits = false;
    trim.note = "battery outside the slide's travel";
  }
  result.trim = trim;
  return result;
}

bool has_stall_glide(const Hydrodynamics& hydro, double pitch_rad) {
  // Descending (nose down) flies alpha > 0, climbing alpha < 0: mirrored,
  // both are the balance at |alpha| with the lift taken along the glide.
  const double direction = pitch_rad < 0.0 ? 1.0 : -1.0;
  const double pitch = std::abs(pitch_rad);
  constexpr double kStep = 5e-4;  // rad: the back-side roots lie ~0.5 deg apart near the onset
  int roots = 0;
  double previous = 0.0;
  for (double a = kStep; a < 0.5 * std::numbers::pi; a += kStep) {
    const ForceCoefficients c = force_coefficients(hydro, direction * a);
    const double balance = std::atan2(c.drag, direction * c.lift) - a - pitch;
    if (a > kStep && (balance < 0.0) != (previous < 0.0)) ++roots;
    previous = balance;
  }
  return roots > 1;
}

}  // namespace glider::model
