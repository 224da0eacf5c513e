// SPDX-License-Identifier: Apache-2.0
#include "glider/science/speed_error_breakdown.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <stdexcept>
#include <utility>

namespace glider::science {
namespace {

constexpr double kDegPerRad = 57.29577951308232;

bool usable(const ScoredSpeedSample& s) {
  return std::isfinite(s.time_s + s.depth_m + s.measured_m_s + s.model_m_s[0] + s.model_m_s[1] + s.pitch_rad +
                       s.depth_rate_measured_m_s + s.depth_rate_model_m_s[0] + s.depth_rate_model_m_s[1]);
}

class RowBuilder {
 public:
  RowBuilder(const std::vector<ScoredSpeedSample>& samples, const std::vector<std::size_t>& used,
             const std::array<double, 2>& total_sq)
      : samples_(samples), used_(used), total_sq_(total_sq) {}

  // A row of the samples where in(i, model) holds; error(i, model) the error counted (default: model - measured).
  void add(std::vector<BreakdownRow>& rows, std::string part, const std::function<bool(std::size_t, int)>& in,
           const std::function<double(std::size_t, int)>& error = {}) const {
    BreakdownRow row;
    row.part = std::move(part);
    std::size_t alpha_count = 0;
    std::array<std::size_t, 2> model_alpha_count{};
    std::array<double, 2> sum{}, sq{};
    for (std::size_t i : used_) {
      const ScoredSpeedSample& s = samples_[i];
      bool any = false;
      for (int k = 0; k < 2; ++k) {
        if (!in(i, k)) continue;
        any = true;
        const double e = error ? error(i, k) : s.model_m_s[k] - s.measured_m_s;
        ++row.samples[k];
        sum[k] += e;
        sq[k] += e * e;
        const double a = implied_alpha_deg(s.model_m_s[k], s.depth_rate_model_m_s[k], s.pitch_rad);
        if (std::isfinite(a)) {
          row.alpha_model_deg[k] += a;
          ++model_alpha_count[k];
        }
      }
      if (!any) continue;
      const double a = implied_alpha_deg(s.measured_m_s, s.depth_rate_measured_m_s, s.pitch_rad);
      if (std::isfinite(a)) {
        row.alpha_measured_deg += a;
        ++alpha_count;
      }
    }
    if (row.samples[0] + row.samples[1] == 0) return;
    for (int k = 0; k < 2; ++k) {
      const double n = static_cast<double>(row.samples[k]);
      row.rms_m_s[k] = row.samples[k] > 0 ? std::sqrt(sq[k] / n) : std::nan("");
      row.mean_m_s[k] = row.samples[k] > 0 ? sum[k] / n : std::nan("");
      row.share[k] = total_sq_[k] > 0.0 ? sq[k] / total_sq_[k] : std::nan("");
      row.alpha_model_deg[k] =
          model_alpha_count[k] > 0 ? row.alpha_model_deg[k] / static_cast<double>(model_alpha_count[k]) : std::nan("");
    }
    row.alpha_measured_deg = alpha_count > 0 ? row.alpha_measured_deg / static_cast<double>(alpha_count) : std::nan("");
    rows.push_back(std::move(row));
  }

 private:
  const std::vector<ScoredSpeedSample>& samples_;
  const std::vector<std::size_t>& used_;
  std::array<double, 2> total_sq_;
};

}  // namespace

double implied_alpha_deg(double speed_m_s, double depth_rate_m_s, double pitch_rad) {
  if (!(speed_m_s > 0.0)) return std::nan("");
  const double s = std::abs(depth_rate_m_s) / speed_m_s;
  if (!(s <= 1.0)) return std::nan("");
  return kDegPerRad * (std::asin(s) - std::abs(pitch_rad));
}

std::vector<BreakdownRow> speed_error_breakdown(const std::vector<ScoredSpeedSample>& samples,
                                                const std::vector<bool>& use, const BreakdownOptions& options) {
  if (use.size() != samples.size()) throw std::invalid_argument("speed_error_breakdown: mask length");
  if (!(options.inflection_s > 0.0 && options.near_surface_m >= 0.0 && options.depth_bin_m > 0.0)) {
    throw std::invalid_argument("speed_error_breakdown: inflection_s and depth_bin_m must be > 0");
  }
  std::vector<std::size_t> used;
  std::array<double, 2> total_sq{};
  // Each yo's dive and climb: the times of their first and last used sample.
  std::map<std::pair<int, bool>, std::pair<double, double>> span;
  std::map<int, std::array<double, 2>> yo_sum;
  std::map<int, std::size_t> yo_count;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const ScoredSpeedSample& s = samples[i];
    if (!use[i] || !usable(s)) continue;
    used.push_back(i);
    for (int k = 0; k < 2; ++k) {
      const double e = s.model_m_s[k] - s.measured_m_s;
      total_sq[k] += e * e;
      yo_sum[s.yo][k] += e;
    }
    ++yo_count[s.yo];
    const auto key = std::make_pair(s.yo, s.pitch_rad > 0.0);
    const auto it = span.find(key);
    if (it == span.end()) {
      span[key] = {s.time_s, s.time_s};
    } else {
      it->second.first = std::min(it->second.first, s.time_s);
      it->second.second = std::max(it->second.second, s.time_s);
    }
  }
  std::vector<BreakdownRow> rows;
  if (used.empty()) return rows;
  const RowBuilder b(samples, used, total_sq);
  auto all = [](std::size_t, int) { return true; };
  b.add(rows, "all", all);
  b.add(rows, "yo means removed", all, [&](std::size_t i, int k) {
    const ScoredSpeedSample& s = samples[i];
    return s.model_m_s[k] - s.measured_m_s - yo_sum[s.yo][k] / static_cast<double>(yo_count[s.yo]);
  });

  // Phase: near-surface first, then the inflections, then the steady dive or climb.
  auto near_surface = [&](std::size_t i) { return samples[i].depth_m < options.near_surface_m; };
  auto from_start = [&](std::size_t i) {
    return samples[i].time_s - span.at({samples[i].yo, samples[i].pitch_rad > 0.0}).first;
  };
  auto to_end = [&](std::size_t i) {
    return span.at({samples[i].yo, samples[i].pitch_rad > 0.0}).second - samples[i].time_s;
  };
  auto steady = [&](std::size_t i) {
    return !near_surface(i) && from_start(i) >= options.inflection_s && to_end(i) >= options.inflection_s;
  };
  b.add(rows, "phase: near-surface", [&](std::size_t i, int) { return near_surface(i); });
  b.add(rows, "phase: leaving an inflection",
        [&](std::size_t i, int) { return !near_surface(i) && from_start(i) < options.inflection_s; });
  b.add(rows, "phase: approaching an inflection", [&](std::size_t i, int) {
    return !near_surface(i) && from_start(i) >= options.inflection_s && to_end(i) < options.inflection_s;
  });
  b.add(rows, "phase: steady dive", [&](std::size_t i, int) { return steady(i) && samples[i].pitch_rad <= 0.0; });
  b.add(rows, "phase: steady climb", [&](std::size_t i, int) { return steady(i) && samples[i].pitch_rad > 0.0; });

  double deepest = 0.0;
  for (std::size_t i : used) deepest = std::max(deepest, samples[i].depth_m);
  for (double top = 0.0; top <= deepest; top += options.depth_bin_m) {
    char name[64];
    std::snprintf(name, sizeof name, "depth %.0f-%.0f m", top, top + options.depth_bin_m);
    b.add(rows, name, [&, top](std::size_t i, int) {
      return samples[i].depth_m >= top && samples[i].depth_m < top + options.depth_bin_m;
    });
  }

  auto error = [&](std::size_t i, int k) { return samples[i].model_m_s[k] - samples[i].measured_m_s; };
  b.add(rows, "sign: model fast", [&](std::size_t i, int k) { return error(i, k) > 0.0; });
  b.add(rows, "sign: model slow", [&](std::size_t i, int k) { return error(i, k) <= 0.0; });
  b.add(rows, "size: error within 1 cm/s", [&](std::size_t i, int k) { return std::abs(error(i, k)) < 0.01; });
  b.add(rows, "size: error 1-3 cm/s either way",
        [&](std::size_t i, int k) { return std::abs(error(i, k)) >= 0.01 && std::abs(error(i, k)) <= 0.03; });
  b.add(rows, "size: error beyond 3 cm/s", [&](std::size_t i, int k) { return std::abs(error(i, k)) > 0.03; });

  auto measured_alpha = [&](std::size_t i) {
    const ScoredSpeedSample& s = samples[i];
    return implied_alpha_deg(s.measured_m_s, s.depth_rate_measured_m_s, s.pitch_rad);
  };
  const std::array<std::pair<double, double>, 5> alpha_bins{
      {{-90.0, kNoLiftAlphaDeg}, {kNoLiftAlphaDeg, 2.0}, {2.0, 3.0}, {3.0, 4.0}, {4.0, 90.0}}};
  const std::array<const char*, 5> alpha_names{{"measured alpha < 1 deg", "measured alpha 1-2 deg",
                                                "measured alpha 2-3 deg", "measured alpha 3-4 deg",
                                                "measured alpha >= 4 deg"}};
  for (std::size_t bin = 0; bin < alpha_bins.size(); ++bin) {
    const auto [lo, hi] = alpha_bins[bin];
    b.add(rows, alpha_names[bin], [&, lo, hi](std::size_t i, int) {
      const double a = measured_alpha(i);
      return a >= lo && a < hi;
    });
  }
  return rows;
}

}  // namespace glider::science
