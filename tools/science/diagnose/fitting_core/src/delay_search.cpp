// SPDX-License-Identifier: Apache-2.0
#include "glider/fitting_core/delay_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace glider::fitting_core {

DelayGrid delay_grid(double low, double high, double step) {
  if (!(step > 0.0) || !(high >= low)) throw std::invalid_argument("delay_grid: step must be > 0 and high >= low");
  DelayGrid grid;
  grid.resolution_s = step;
  const auto n = static_cast<std::size_t>(std::floor((high - low) / step + 1e-9));
  for (std::size_t i = 0; i <= n; ++i) grid.values.push_back(low + step * static_cast<double>(i));
  return grid;
}

DelayGrid doubling_delay_grid(double step, double high) {
  if (!(step > 0.0) || !(high >= step)) throw std::invalid_argument("doubling_delay_grid: need 0 < step <= high");
  DelayGrid grid;
  grid.values = {0.0, 0.5 * step};
  for (double x = step; x < high; x *= 2.0) grid.values.push_back(x);
  grid.values.push_back(high);
  grid.resolution_s = grid.values.back() - grid.values[grid.values.size() - 2];
  return grid;
}

double resolution_at(const DelayGrid& grid, double value) {
  const auto after = std::upper_bound(grid.values.begin(), grid.values.end(), value);
  if (after == grid.values.begin()) return grid.values[1] - grid.values[0];
  if (after == grid.values.end()) return grid.values.back() - grid.values[grid.values.size() - 2];
  return *after - *(after - 1);
}

double best_on_grid(const DelayGrid& grid, const std::vector<double>& rss) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < rss.size(); ++i) {
    if (rss[i] < rss[best] || !(rss[best] == rss[best])) best = i;  // NaN never wins
  }
  // A residual read at a log's cycle is flat in the delay between cycles:
  // of a run of equal minima, its middle (a local fit cannot leave a flat).
  std::size_t last = best;
  while (last + 1 < rss.size() && rss[last + 1] == rss[best]) ++last;
  return 0.5 * (grid.values[best] + grid.values[last]);
}

std::vector<double> rss_on_grid(const DelayGrid& grid, const std::function<double(double)>& objective) {
  std::vector<double> rss;
  rss.reserve(grid.values.size());
  for (double x : grid.values) rss.push_back(objective(x));
  return rss;
}

double profile_threshold(double best_rss, double n_eff, int k) {
  return best_rss * (1.0 + 3.84 / std::max(1.0, n_eff - static_cast<double>(k)));
}

Interval profile_interval(const DelayGrid& grid, const std::vector<double>& rss, double value, double fitted_rss,
                          double n_eff, int k) {
  double best = std::isfinite(fitted_rss) ? fitted_rss : std::numeric_limits<double>::infinity();
  for (double r : rss) best = std::min(best, r);
  const double limit = profile_threshold(best, n_eff, k);
  // The grid values inside (and `value`'s cell); the bound lies between the
  // last grid value inside and the first outside: the interval reaches the
  // first outside (the grid's resolution there).
  const auto cell = std::upper_bound(grid.values.begin(), grid.values.end(), value);
  std::size_t first = cell == grid.values.begin() ? 0 : static_cast<std::size_t>(cell - grid.values.begin()) - 1;
  std::size_t last = std::min(first + 1, grid.values.size() - 1);
  if (grid.values[first] == value) last = first;
  for (std::size_t i = 0; i < rss.size(); ++i) {
    if (!(rss[i] <= limit)) continue;
    first = std::min(first, i);
    last = std::max(last, i);
  }
  Interval out;
  out.low = grid.values[first == 0 ? 0 : first - 1];
  out.high = grid.values[std::min(last + 1, grid.values.size() - 1)];
  out.low = std::min(out.low, value);
  out.high = std::max(out.high, value);
  return out;
}

Interval at_least_resolution(Interval interval, double value, double resolution, double floor) {
  if (interval.high - interval.low >= resolution) return interval;
  interval.low = std::min(interval.low, value - 0.5 * resolution);
  interval.high = std::max(interval.high, value + 0.5 * resolution);
  if (interval.low < floor) {
    interval.high += floor - interval.low;
    interval.low = floor;
  }
  return interval;
}

bool jacobian_failed(double half_width, double scale) {
  return !std::isfinite(half_width) || half_width <= 1e-6 * scale;
}

}  // namespace glider::fitting_core
