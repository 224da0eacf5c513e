// SPDX-License-Identifier: Apache-2.0
#include "glider/science/gliderflight_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

namespace glider::science {
namespace {

constexpr double kG = 9.81;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Linear interpolation of (x, y) at xi, x increasing; clamped at the ends (np.interp).
double interp(const std::vector<double>& x, const std::vector<double>& y, double xi, std::size_t& hint) {
  if (xi <= x.front()) return y.front();
  if (xi >= x.back()) return y.back();
  while (hint + 1 < x.size() && x[hint + 1] < xi) ++hint;
  while (hint > 0 && x[hint] > xi) --hint;
  const double f = (xi - x[hint]) / (x[hint + 1] - x[hint]);
  return y[hint] + f * (y[hint + 1] - y[hint]);
}

// The steady angle of attack at |pitch|: the smallest root of
// (C_D0 + C_D1 a^2) / ((a_h + a_w) tan(a + pitch)) - a, found by stepping up
// from 0 to the first sign change and bisecting (the flight branch; a second
// root at large angles is the stalled one).
double steady_alpha(const GliderflightParameters& p, double aw, double pitch) {
  auto f = [&](double a) { return (p.cd0 + p.cd1 * a * a) / ((p.ah + aw) * std::tan(a + pitch)) - a; };
  const double top = 0.5 * std::numbers::pi - pitch;
  double lo = 0.0, hi = 0.0;
  const double step = 1e-3;
  for (double a = step; a < top; a += step) {
    if (f(a) < 0.0) {
      hi = a;
      lo = a - step;
      break;
    }
  }
  if (hi == 0.0) return kNaN;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void check(const GliderflightInput& in) {
  const std::size_t n = in.time_s.size();
  if (n < 3 || in.pressure_bar.size() != n || in.pitch_rad.size() != n || in.buoyancy_change_cc.size() != n ||
      in.density_kg_m3.size() != n) {
    throw std::invalid_argument("gliderflight model: the input columns differ in length or have fewer than 3 records");
  }
  if (!in.water_w_down_m_s.empty() && in.water_w_down_m_s.size() != n) {
    throw std::invalid_argument("gliderflight model: " + std::to_string(in.water_w_down_m_s.size()) +
                                " water velocities for " + std::to_string(n) + " records");
  }
  for (std::size_t i = 0; i < in.water_w_down_m_s.size(); ++i) {
    if (!std::isfinite(in.water_w_down_m_s[i]) || std::abs(in.water_w_down_m_s[i]) > 1.0) {
      throw std::invalid_argument("gliderflight model: record " + std::to_string(i) + " water velocity " +
                                  std::to_string(in.water_w_down_m_s[i]) + " m/s (allowed: finite, within +-1 m/s)");
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(in.time_s[i] + in.pressure_bar[i] + in.pitch_rad[i] + in.buoyancy_change_cc[i] +
                       in.density_kg_m3[i])) {
      throw std::invalid_argument("gliderflight model: record " + std::to_string(i) +
                                  " has a missing time, pressure, pitch, buoyancy change or density");
    }
    if (i > 0 && !(in.time_s[i] > in.time_s[i - 1])) {
      throw std::invalid_argument("gliderflight model: time not increasing at record " + std::to_string(i));
    }
  }
}

GliderflightResult solve_steady(const GliderflightParameters& p, const GliderflightInput& in) {
  const double aw = p.aw();
  // gliderflight tabulates the angle of attack at 100 pitches from 0.05 to
  // 60 deg and interpolates linearly; outside the table the angle is 0.
  constexpr int kTable = 100;
  std::vector<double> pitch_i(kTable), alpha_i(kTable);
  const double lo = 0.05 * std::numbers::pi / 180.0, hi = 60.0 * std::numbers::pi / 180.0;
  for (int k = 0; k < kTable; ++k) {
    pitch_i[k] = lo + (hi - lo) * k / (kTable - 1);
    alpha_i[k] = steady_alpha(p, aw, pitch_i[k]);
  }
  GliderflightResult r;
  const std::size_t n = in.time_s.size();
  r.speed_m_s.resize(n);
  r.w_m_s.resize(n);
  r.alpha_rad.resize(n);
  std::size_t hint = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double pitch = in.pitch_rad[i];
    const double a = std::abs(pitch);
    const double alpha = a >= lo && a <= hi ? std::copysign(interp(pitch_i, alpha_i, a, hint), pitch) : 0.0;
    const double fb =
        kG * in.density_kg_m3[i] *
        (p.volume_m3 * (1.0 - p.epsilon_per_pa * in.pressure_bar[i] * 1e5) + in.buoyancy_change_cc[i] * 1e-6);
    const double q = (fb - p.mass_kg * kG) * std::sin(pitch + alpha) / (p.cd0 + p.cd1 * alpha * alpha);
    const double u2 = std::max(0.0, 2.0 * q / in.density_kg_m3[i] / p.area_m2);
    r.speed_m_s[i] = std::sqrt(u2);
    r.alpha_rad[i] = alpha;
    r.w_m_s[i] = r.speed_m_s[i] * std::sin(pitch + alpha);
  }
  return r;
}

GliderflightResult solve_dynamic(const GliderflightParameters& p, const GliderflightInput& in) {
  const double aw = p.aw();
  const double h = p.dt_s;
  const double t0 = in.time_s.front(), t1 = in.time_s.back();
  const std::size_t m = static_cast<std::size_t>(std::floor((t1 + h - t0) / h)) + 1;  // np.arange(t0, t1 + h, h)
  struct Node {
    double fbg, pitch, rho, surface, m11, m12, m21, m22;
  };
  std::vector<Node> node(m);
  std::vector<double> ti(m);
  std::size_t h_p = 0, h_r = 0, h_v = 0, h_pr = 0;
  const double added1 = p.k1 * p.mass_kg, added2 = p.k2 * p.mass_kg;
  const double denom = p.mass_kg * p.mass_kg + (added2 + added1) * p.mass_kg + added1 * added2;
  for (std::size_t k = 0; k < m; ++k) {
    ti[k] = t0 + h * static_cast<double>(k);
    const double pitch = interp(in.time_s, in.pitch_rad, ti[k], h_p);
    const double pressure_pa = interp(in.time_s, in.pressure_bar, ti[k], h_pr) * 1e5;
    const double rho = interp(in.time_s, in.density_kg_m3, ti[k], h_r);
    const double vbp = interp(in.time_s, in.buoyancy_change_cc, ti[k], h_v) * 1e-6;
    const double fb = kG * rho * (p.volume_m3 * (1.0 - p.epsilon_per_pa * pressure_pa) + vbp);
    const double c2 = std::cos(pitch) * std::cos(pitch), cs = std::cos(pitch) * std::sin(pitch);
    node[k] = {fb - p.mass_kg * kG,
               pitch,
               rho,
               pressure_pa < p.surface_m * 1e4 ? 1.0 : 0.0,
               ((added2 - added1) * c2 + added1 + p.mass_kg) / denom,
               (added2 - added1) * cs / denom,
               (added2 - added1) * cs / denom,
               (-(added2 - added1) * c2 + added2 + p.mass_kg) / denom};
  }
  auto rate = [&](double u, double w, const Node& d, double& ku, double& kw) {
    const double speed = std::sqrt(u * u + w * w);
    const double alpha = std::atan2(w, u) - d.pitch;
    const double q = 0.5 * d.rho * p.area_m2 * speed * speed;
    const double lift = q * (aw + p.ah) * alpha;
    const double drag = q * (p.cd0 + p.cd1 * alpha * alpha);
    const double gamma = d.pitch + alpha;
    const double fx = -std::cos(gamma) * drag + std::sin(gamma) * lift;
    const double fy = -std::cos(gamma) * lift - std::sin(gamma) * drag + d.fbg;
    ku = h * (d.m11 * fx + d.m12 * fy);
    kw = h * (d.m21 * fx + d.m22 * fy);
  };
  std::vector<double> u(m, 0.0), w(m, 0.0);
  for (std::size_t k = 0; k + 1 < m; ++k) {
    if (node[k].surface != 0.0) {
      u[k + 1] = w[k + 1] = 0.0;
      continue;
    }
    // The middle stages use the inputs averaged over the step (gliderflight's data_mid).
    const Node& a = node[k];
    const Node& c = node[k + 1];
    const Node mid{0.5 * (a.fbg + c.fbg),         0.5 * (a.pitch + c.pitch), 0.5 * (a.rho + c.rho),
                   0.5 * (a.surface + c.surface), 0.5 * (a.m11 + c.m11),     0.5 * (a.m12 + c.m12),
                   0.5 * (a.m21 + c.m21),         0.5 * (a.m22 + c.m22)};
    double k1u, k1w, k2u, k2w, k3u, k3w, k4u, k4w;
    rate(u[k], w[k], a, k1u, k1w);
    rate(u[k] + 0.5 * k1u, w[k] + 0.5 * k1w, mid, k2u, k2w);
    rate(u[k] + 0.5 * k2u, w[k] + 0.5 * k2w, mid, k3u, k3w);
    rate(u[k] + k3u, w[k] + k3w, c, k4u, k4w);
    u[k + 1] = u[k] + (k1u + 2.0 * k2u + 2.0 * k3u + k4u) / 6.0;
    w[k + 1] = w[k] + (k1w + 2.0 * k2w + 2.0 * k3w + k4w) / 6.0;
  }
  std::vector<double> speed(m), alpha(m);
  for (std::size_t k = 0; k < m; ++k) {
    speed[k] = std::sqrt(u[k] * u[k] + w[k] * w[k]);
    alpha[k] = std::atan2(w[k], u[k]) - node[k].pitch;
  }
  // The results on the records' times (np.interp), as gliderflight returns them.
  GliderflightResult r;
  const std::size_t n = in.time_s.size();
  r.speed_m_s.resize(n);
  r.alpha_rad.resize(n);
  r.w_m_s.resize(n);
  std::size_t h1 = 0, h2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    r.speed_m_s[i] = interp(ti, speed, in.time_s[i], h1);
    r.alpha_rad[i] = interp(ti, alpha, in.time_s[i], h2);
    r.w_m_s[i] = r.speed_m_s[i] * std::sin(in.pitch_rad[i] + r.alpha_rad[i]);
  }
  return r;
}

}  // namespace

double GliderflightParameters::aw() const {
  const double t = std::tan(sweep_rad);
  return 2.0 * std::numbers::pi * aspect_ratio / (2.0 + std::sqrt(aspect_ratio * aspect_ratio * (1.0 + t * t) + 4.0));
}

std::vector<double> gliderflight_depth_rate(const GliderflightInput& in, double rho0_kg_m3) {
  const std::size_t n = in.time_s.size();
  std::vector<double> out(n, kNaN);
  if (n < 2) return out;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 < n ? i + 1 : i;
    const double dp = (in.pressure_bar[b] - in.pressure_bar[a]) * 1e5, dt = in.time_s[b] - in.time_s[a];
    out[i] = -dp / dt / rho0_kg_m3 / kG;
  }
  return out;
}

GliderflightResult gliderflight_solve(GliderflightKind kind, const GliderflightParameters& p,
                                      const GliderflightInput& in) {
  check(in);
  return kind == GliderflightKind::kSteady ? solve_steady(p, in) : solve_dynamic(p, in);
}

GliderflightParameters gliderflight_calibrate(GliderflightKind kind, GliderflightParameters p,
                                              const GliderflightInput& in, const std::vector<bool>& fit,
                                              double* rms_m_s, GliderflightFit what) {
  check(in);
  if (fit.size() != in.time_s.size()) throw std::invalid_argument("gliderflight calibration: mask length");
  const std::vector<double> dhdt = gliderflight_depth_rate(in, p.rho0_kg_m3);
  // The fitted parameters, in order, and the scales of the stopping rule.
  const std::size_t dims = what == GliderflightFit::kCd0MassEpsilon ? 3 : 2;
  using Point = std::vector<double>;
  const Point scale{0.15, 70.0, 5e-10};
  auto with = [&](const Point& x) {
    GliderflightParameters q = p;
    q.cd0 = x[0];
    q.mass_kg = x[1];
    if (dims == 3) q.epsilon_per_pa = x[2];
    return q;
  };
  // How many fitted records each evaluated point's model is finite at: the
  // stopping rule's test for a fit that has left the model's domain.
  std::map<Point, std::size_t> finite_at;
  std::size_t fitted_records = 0;
  for (const bool use : fit) fitted_records += use ? 1 : 0;
  auto cost = [&](const Point& x) {
    const GliderflightParameters q = with(x);
    finite_at[x] = 0;
    if (!(q.cd0 > 0.0)) return std::numeric_limits<double>::infinity();
    const GliderflightResult r = kind == GliderflightKind::kSteady ? solve_steady(q, in) : solve_dynamic(q, in);
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < fit.size(); ++i) {
      if (!fit[i]) continue;
      const double water_up = in.water_w_down_m_s.empty() ? 0.0 : -in.water_w_down_m_s[i];
      const double e = r.w_m_s[i] + water_up - dhdt[i];
      if (!std::isfinite(e)) continue;  // np.nanmean
      sum += e * e;
      ++count;
    }
    finite_at[x] = count;
    return count > 0 ? sum / static_cast<double>(count) : std::numeric_limits<double>::infinity();
  };
  // Nelder-Mead (reflection 1, expansion 2, contraction 1/2, shrink 1/2),
  // the start simplex as scipy's fmin: each coordinate moved by 5 %.
  Point start{p.cd0, p.mass_kg};
  if (dims == 3) start.push_back(p.epsilon_per_pa);
  std::vector<Point> x(dims + 1, start);
  for (std::size_t j = 0; j < dims; ++j) x[j + 1][j] = 1.05 * start[j];
  std::vector<double> f(dims + 1);
  for (std::size_t k = 0; k <= dims; ++k) f[k] = cost(x[k]);
  for (int iteration = 0; iteration < 4000 * static_cast<int>(dims - 1); ++iteration) {
    std::vector<std::size_t> order(dims + 1);
    for (std::size_t k = 0; k <= dims; ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return f[a] < f[b]; });
    std::vector<Point> sorted_x(dims + 1);
    std::vector<double> sorted_f(dims + 1);
    for (std::size_t k = 0; k <= dims; ++k) {
      sorted_x[k] = x[order[k]];
      sorted_f[k] = f[order[k]];
    }
    x = std::move(sorted_x);
    f = std::move(sorted_f);
    const Point& best = x[0];
    const Point worst = x[dims];
    const double fb = f[0], fm = f[dims - 1], fw = f[dims];
    double size = 0.0;
    for (std::size_t k = 1; k <= dims; ++k) {
      for (std::size_t j = 0; j < dims; ++j) size = std::max(size, std::abs(x[k][j] - best[j]) / scale[j]);
    }
    if (size < 1e-9 && fw - fb <= 1e-16) break;
    // Diverged: past scipy fmin's own iteration limit (200 per parameter),
    // the best point's model still not finite at most of the fitted records
    // (the dynamic model's RK4 blows up on them; np.nanmean drops them, so
    // the cost is over the few left and the simplex wanders on without
    // converging, to the cap). Such a fit has no meaning: stop (the protocol
    // reports the model as diverged). A start that diverges (m_g far from
    // the glider's) is left the 200 per parameter to walk out of it; the fits
    // that converge do so in ~70 iterations.
    if (iteration >= 200 * static_cast<int>(dims) && 2 * finite_at[best] < fitted_records) break;
    Point centre(dims, 0.0);
    for (std::size_t j = 0; j < dims; ++j) {
      double sum = 0.0;
      for (std::size_t k = 0; k < dims; ++k) sum += x[k][j];
      centre[j] = (1.0 / static_cast<double>(dims)) * sum;
    }
    auto along = [&](double t) {
      Point out(dims);
      for (std::size_t j = 0; j < dims; ++j) out[j] = centre[j] + t * (worst[j] - centre[j]);
      return out;
    };
    const Point xr = along(-1.0);
    const double fr = cost(xr);
    if (fr < fb) {
      const Point xe = along(-2.0);
      const double fe = cost(xe);
      if (fe < fr) {
        x[dims] = xe;
        f[dims] = fe;
      } else {
        x[dims] = xr;
        f[dims] = fr;
      }
    } else if (fr < fm) {
      x[dims] = xr;
      f[dims] = fr;
    } else {
      const Point xc = fr < fw ? along(-0.5) : along(0.5);
      const double fc = cost(xc);
      if (fc < std::min(fr, fw)) {
        x[dims] = xc;
        f[dims] = fc;
      } else {
        for (std::size_t k = 1; k <= dims; ++k) {
          for (std::size_t j = 0; j < dims; ++j) x[k][j] = x[0][j] + 0.5 * (x[k][j] - x[0][j]);
          f[k] = cost(x[k]);
        }
      }
    }
  }
  const std::size_t b = static_cast<std::size_t>(std::min_element(f.begin(), f.end()) - f.begin());
  p = with(x[b]);
  if (rms_m_s != nullptr) *rms_m_s = std::sqrt(f[b]);
  return p;
}

bool gliderflight_diverged(const GliderflightResult& r, const std::vector<bool>& fit) {
  if (r.w_m_s.size() != fit.size()) throw std::invalid_argument("gliderflight_diverged: mask length");
  std::size_t fitted = 0, finite = 0;
  for (std::size_t i = 0; i < fit.size(); ++i) {
    if (!fit[i]) continue;
    ++fitted;
    if (std::isfinite(r.w_m_s[i])) ++finite;
  }
  return 2 * finite < fitted;
}

}  // namespace glider::science
