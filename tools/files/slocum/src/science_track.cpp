// SPDX-License-Identifier: Apache-2.0
#include "science_track.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <string_view>

namespace glider::slocum::detail {
namespace {

constexpr double kEmpty = std::numeric_limits<double>::quiet_NaN();
constexpr std::string_view kCtdTimestamp = "sci_ctd41cp_timestamp";
constexpr std::array<std::string_view, 3> kCtdValues = {"sci_water_pressure", "sci_water_temp", "sci_water_cond"};

bool is_ctd_sensor(std::string_view name) {
  return name == kCtdTimestamp || name == kCtdValues[0] || name == kCtdValues[1] || name == kCtdValues[2];
}

// The sensor's value in each cycle it was set, NaN elsewhere.
std::vector<double> per_cycle(const BinaryFile& file, std::string_view name) {
  std::vector<double> values(file.cycle_count(), kEmpty);
  if (const auto i = file.index_of(name)) {
    const SensorSeries& s = file.series()[*i];
    for (std::size_t k = 0; k < s.cycles.size(); ++k) values[s.cycles[k]] = s.values[k];
  }
  return values;
}

}  // namespace

ScienceTrack::ScienceTrack(const std::vector<BinaryFile>& files, double max_gap_s)
    : files_(files), max_gap_s_(max_gap_s) {
  for (const BinaryFile& file : files) {
    std::vector<bool>& bad = bad_ctd_.emplace_back(file.cycle_count(), false);
    const std::vector<double> stamp = per_cycle(file, kCtdTimestamp);
    std::array<std::vector<double>, 3> ctd;
    for (std::size_t j = 0; j < ctd.size(); ++j) ctd[j] = per_cycle(file, kCtdValues[j]);
    for (std::size_t c = 0; c < file.cycle_count(); ++c) {
      const bool stamp_bad = !std::isnan(stamp[c]) && stamp[c] <= 0.0;
      const bool all_zero = ctd[0][c] == 0.0 && ctd[1][c] == 0.0 && ctd[2][c] == 0.0;
      bad[c] = stamp_bad || all_zero;
    }
  }
}

flightlog::Column ScienceTrack::interpolate(const std::string& name, const std::vector<double>& time,
                                            std::map<std::string, std::size_t>& non_finite) const {
  // The samples, in order, strictly increasing in time.
  std::vector<double> t;
  std::vector<double> y;
  const bool ctd = is_ctd_sensor(name);
  for (std::size_t f = 0; f < files_.size(); ++f) {
    const BinaryFile& file = files_[f];
    const auto i = file.index_of(name);
    if (!i) continue;
    const SensorSeries& s = file.series()[*i];
    for (std::size_t k = 0; k < s.cycles.size(); ++k) {
      const std::uint32_t c = s.cycles[k];
      if (ctd && bad_ctd_[f][c]) continue;
      const double v = s.values[k];
      if (!std::isfinite(v)) {
        ++non_finite[name];
        continue;
      }
      const double tc = file.cycle_time()[c];
      if (!(t.empty() || tc > t.back())) continue;
      t.push_back(tc);
      y.push_back(v);
    }
  }
  flightlog::Column out(time.size(), kEmpty);
  if (t.empty()) return out;
  std::size_t k = 0;  // t[k] <= x < t[k + 1]
  for (std::size_t r = 0; r < time.size(); ++r) {
    const double x = time[r];
    if (!(x >= t.front() && x <= t.back())) continue;
    while (k + 1 < t.size() && t[k + 1] <= x) ++k;
    if (t[k] == x) {
      out[r] = y[k];
    } else if (t[k + 1] - t[k] < max_gap_s_) {
      // numpy.interp's arithmetic, so the values match the shared CSVs.
      const double slope = (y[k + 1] - y[k]) / (t[k + 1] - t[k]);
      out[r] = slope * (x - t[k]) + y[k];
    }
  }
  return out;
}

}  // namespace glider::slocum::detail
