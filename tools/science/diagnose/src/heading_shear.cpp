// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/heading_shear.hpp"

#include <algorithm>
#include <cmath>

#include "glider/diagnose/trend.hpp"
#include "glider/model/dynamics.hpp"

namespace glider::diagnose {
namespace {

struct Sums {
  double xx = 0.0, xr = 0.0;
};

std::size_t bin_of(double depth_m, double bin_m) {
  return static_cast<std::size_t>(std::max(0.0, std::floor(depth_m / bin_m)));
}

// Per glide and bin, the sums of the regressor x and residual r.
std::vector<std::vector<Sums>> per_run(const HeadingTrack& t, std::span<const double> residual,
                                       std::span<const std::size_t> samples, double bin_m, std::size_t bins,
                                       int want_phase) {
  std::vector<std::vector<Sums>> out(t.run_first.size(), std::vector<Sums>(bins));
  std::size_t run = 0;
  for (const std::size_t i : samples) {
    while (run + 1 < t.run_first.size() && i >= t.run_first[run + 1]) ++run;
    if (!std::isfinite(residual[i]) || !std::isfinite(t.depth_m[i])) continue;
    if (want_phase >= 0 && static_cast<int>(t.phase[i]) != want_phase) continue;
    const double x = shear_yaw_per_unit(t, i);
    if (!std::isfinite(x)) continue;
    Sums& s = out[run][std::min(bins - 1, bin_of(t.depth_m[i], bin_m))];
    s.xx += x * x;
    s.xr += x * residual[i];
  }
  return out;
}

// The pooled per-bin estimate over the runs of the wanted yo parity (-1: all).
std::vector<double> pooled(const HeadingTrack& t, const std::vector<std::vector<Sums>>& runs, int parity) {
  const std::size_t bins = runs.empty() ? 0 : runs.front().size();
  std::vector<double> xx(bins, 0.0), xr(bins, 0.0), s(bins, std::nan(""));
  for (std::size_t run = 0; run < runs.size(); ++run) {
    if (parity >= 0 && t.yo[t.run_first[run]] % 2 != parity) continue;
    for (std::size_t b = 0; b < bins; ++b) {
      xx[b] += runs[run][b].xx;
      xr[b] += runs[run][b].xr;
    }
  }
  for (std::size_t b = 0; b < bins; ++b) {
    if (xx[b] > 0.0) s[b] = xr[b] / xx[b];
  }
  return s;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0.0, mb = 0.0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (std::isfinite(a[k]) && std::isfinite(b[k])) {
      ma += a[k];
      mb += b[k];
      ++n;
    }
  }
  if (n < 3) return 0.0;
  ma /= static_cast<double>(n);
  mb /= static_cast<double>(n);
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (std::isfinite(a[k]) && std::isfinite(b[k])) {
      ab += (a[k] - ma) * (b[k] - mb);
      aa += (a[k] - ma) * (a[k] - ma);
      bb += (b[k] - mb) * (b[k] - mb);
    }
  }
  return aa > 0.0 && bb > 0.0 ? ab / std::sqrt(aa * bb) : 0.0;
}

}  // namespace

double shear_yaw_per_unit(const HeadingTrack& t, std::size_t i) {
  return model::shear_turn_per_unit(t.depth_rate_m_s[i], t.speed_m_s[i]);
}

ShearProfile fit_current_shear(const HeadingTrack& t, std::span<const double> residual,
                               std::span<const std::size_t> samples, double bin_m) {
  ShearProfile p;
  double deepest = 0.0;
  for (const std::size_t i : samples) {
    if (std::isfinite(t.depth_m[i])) deepest = std::max(deepest, t.depth_m[i]);
  }
  const std::size_t bins = bin_of(deepest, bin_m) + 1;
  const auto runs = per_run(t, residual, samples, bin_m, bins, -1);
  const std::vector<double> fitted = pooled(t, runs, 0);
  for (std::size_t b = 0; b < bins; ++b) {
    ShearBin bin;
    bin.from_m = static_cast<double>(b) * bin_m;
    bin.to_m = bin.from_m + bin_m;
    // The interval: the fitted yos' glides, each its own estimate (their
    // yaw residuals are correlated within a glide, not across glides).
    std::vector<double> each;
    for (std::size_t run = 0; run < runs.size(); ++run) {
      if (t.yo[t.run_first[run]] % 2 == 0 && runs[run][b].xx > 0.0) each.push_back(runs[run][b].xr / runs[run][b].xx);
    }
    bin.runs = each.size();
    bin.fitted = each.size() >= 2 && std::isfinite(fitted[b]);
    if (bin.fitted) {
      const Interval spread = mean_with_interval(each);
      const double half = spread.high - spread.value;
      bin.shear_per_s = fitted[b];
      bin.ci95_low = fitted[b] - half;
      bin.ci95_high = fitted[b] + half;
    }
    p.bins.push_back(bin);
  }
  double before = 0.0, after = 0.0;
  std::size_t n = 0;
  for (const std::size_t i : samples) {
    if (t.yo[i] % 2 == 0 || !std::isfinite(residual[i]) || !std::isfinite(t.depth_m[i])) continue;
    const double left = residual[i] - shear_at(p, t.depth_m[i]) * shear_yaw_per_unit(t, i);
    if (!std::isfinite(left)) continue;
    before += residual[i] * residual[i];
    after += left * left;
    ++n;
  }
  if (n > 0) {
    p.heldout_rms_before = std::sqrt(before / static_cast<double>(n));
    p.heldout_rms_after = std::sqrt(after / static_cast<double>(n));
  }
  p.dive_climb_correlation = correlation(
      pooled(t, per_run(t, residual, samples, bin_m, bins, static_cast<int>(flightlog::Phase::kDive)), -1),
      pooled(t, per_run(t, residual, samples, bin_m, bins, static_cast<int>(flightlog::Phase::kClimb)), -1));
  return p;
}

double shear_at(const ShearProfile& p, double depth_m) {
  for (const ShearBin& b : p.bins) {
    if (depth_m >= b.from_m && depth_m < b.to_m) return b.fitted ? b.shear_per_s : 0.0;
  }
  return 0.0;
}

}  // namespace glider::diagnose
