// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/depth_rate_calibration.hpp"

#include <cmath>
#include <cstdio>
#include <functional>

#include "glider/model/steady_glide.hpp"

namespace glider::forecast {

namespace {

constexpr int kScanPoints = 48;  // the bracket's scan: finds a sign change past no-glide pitches
constexpr int kBisections = 50;

// |depth rate| of a steady glide at a signed pitch and net buoyancy (kg, + heavy); NaN: no glide.
double glide_rate(const model::PitchGlideSolver& solver, double density, double pitch_rad, double buoyancy_kg) {
  const model::SteadyGlideResult r = solver.solve(density, pitch_rad, buoyancy_kg);
  return r.glide ? std::fabs(r.glide->depth_rate_m_s) : std::nan("");
}

// The net buoyancy (signed as the glide: + heavy diving, - light climbing)
// that glides at |depth rate| `target` at `pitch_rad`; NaN: none within 2 kg.
double buoyancy_for_rate(const model::PitchGlideSolver& solver, double density, double pitch_rad, double target) {
  const double sign = pitch_rad < 0.0 ? 1.0 : -1.0;
  double lo = 1e-5, hi = 2.0;
  const double at_lo = glide_rate(solver, density, pitch_rad, sign * lo);
  const double at_hi = glide_rate(solver, density, pitch_rad, sign * hi);
  if (!std::isfinite(at_lo) || !std::isfinite(at_hi) || !(at_lo <= target && target <= at_hi)) return std::nan("");
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double at = glide_rate(solver, density, pitch_rad, sign * mid);
    if (!std::isfinite(at)) return std::nan("");
    (at < target ? lo : hi) = mid;
  }
  return sign * 0.5 * (lo + hi);
}

// A root of f over [lo, hi]: the first sign change of a scan among finite
// values, then bisection. NaN: none.
double root(const std::function<double(double)>& f, double lo, double hi) {
  double last_x = std::nan(""), last_f = std::nan("");
  for (int i = 0; i <= kScanPoints; ++i) {
    const double x = lo + (hi - lo) * i / kScanPoints;
    const double fx = f(x);
    if (!std::isfinite(fx)) continue;
    if (std::isfinite(last_f) && (fx == 0.0 || (fx > 0.0) != (last_f > 0.0))) {
      double a = last_x, b = x, fa = last_f;
      for (int k = 0; k < kBisections; ++k) {
        const double m = 0.5 * (a + b);
        const double fm = f(m);
        if (!std::isfinite(fm)) break;
        if ((fm > 0.0) == (fa > 0.0)) {
          a = m;
          fa = fm;
        } else {
          b = m;
        }
      }
      return 0.5 * (a + b);
    }
    last_x = x;
    last_f = fx;
  }
  return std::nan("");
}

}  // namespace

DepthRateCalibration calibrate_depth_rates(const model::Hydrodynamics& hydro, double density, const GlidePitch& glider,
                                           const GlidePitch& model, bool servo) {
  DepthRateCalibration c;
  c.servo = servo;
  if (glider.dive_n < kDepthRateMinSamples || glider.climb_n < kDepthRateMinSamples ||
      model.dive_n < kDepthRateMinSamples || model.climb_n < kDepthRateMinSamples) {
    c.why_not = "fewer than 20 steady samples of dives or climbs (the glider's or the model's)";
    return c;
  }
  c.glider_dive_m_s = glider.dive_rate_m_s();
  c.glider_climb_m_s = glider.climb_rate_m_s();
  c.model_dive_m_s = model.dive_rate_m_s();
  c.model_climb_m_s = model.climb_rate_m_s();
  const double model_dive_pitch = model.dive_rad(), model_climb_pitch = model.climb_rad();
  const model::PitchGlideSolver nominal(hydro);
  // The model's own net buoyancy each way, at its own pitch.
  const double model_dive_b = buoyancy_for_rate(nominal, density, -model_dive_pitch, c.model_dive_m_s);
  const double model_climb_b = buoyancy_for_rate(nominal, density, model_climb_pitch, c.model_climb_m_s);
  if (!std::isfinite(model_dive_b) || !std::isfinite(model_climb_b)) {
    c.why_not = "the model's own glides are not on its steady polar";
    return c;
  }
  // For a cause's value x: the buoyancy offset that makes the dive the
  // glider's, then the climb's miss with it (monotone in x).
  double offset = 0.0;
  const auto climb_miss = [&](double x) {
    model::Hydrodynamics h = hydro;
    if (!servo) model::scale_drag(h, x);
    const model::PitchGlideSolver solver(h);
    const double dive_pitch = servo ? x * glider.dive_rad() : model_dive_pitch;
    const double climb_pitch = servo ? x * glider.climb_rad() : model_climb_pitch;
    const double dive_b = buoyancy_for_rate(solver, density, -dive_pitch, c.glider_dive_m_s);
    if (!std::isfinite(dive_b)) return std::nan("");
    offset = dive_b - model_dive_b;
    const double climb_b = model_climb_b + offset;
    if (!(climb_b < 0.0)) return -c.glider_climb_m_s;  // it would not climb
    return glide_rate(solver, density, climb_pitch, climb_b) - c.glider_climb_m_s;
  };
  const double x = servo ? root(climb_miss, kDepthRateScaleMin, kDepthRateScaleMax)
                         : root(climb_miss, kDepthRateDragMin, kDepthRateDragMax);
  if (!std::isfinite(x) || !std::isfinite(climb_miss(x))) {
    char text[200];
    std::snprintf(text, sizeof text, "no %s in [%.2f, %.2f] glides at both rates", servo ? "pitch scale" : "drag",
                  servo ? kDepthRateScaleMin : kDepthRateDragMin, servo ? kDepthRateScaleMax : kDepthRateDragMax);
    c.why_not = text;
    return c;
  }
  if (!(std::fabs(offset) <= kDepthRateBuoyancyMaxKg)) {
    char text[200];
    std::snprintf(text, sizeof text, "a buoyancy offset of %+.0f g would be needed (beyond %.0f g: another trim)",
                  1000.0 * offset, 1000.0 * kDepthRateBuoyancyMaxKg);
    c.why_not = text;
    return c;
  }
  c.buoyancy_kg = offset;
  if (servo) {
    c.pitch_scale = x;
    c.dive_pitch_factor = x * glider.dive_rad() / model_dive_pitch;
    c.climb_pitch_factor = x * glider.climb_rad() / model_climb_pitch;
  } else {
    c.drag_factor = x;
  }
  c.have = true;
  return c;
}

}  // namespace glider::forecast
