// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/stored_on_change.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "glider/flightlog/gaps.hpp"

namespace glider::diagnose {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double quantile(std::vector<double> x, double q) {
  const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(x.size() - 1));
  std::nth_element(x.begin(), x.begin() + k, x.end());
  return x[static_cast<std::size_t>(k)];
}

}  // namespace

double storing_interval_s(std::span<const double> time, std::span<const double> values) {
  std::vector<double> gaps;
  double last = kNaN;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) continue;
    if (std::isfinite(last) && time[i] > last) gaps.push_back(time[i] - last);
    last = time[i];
  }
  return gaps.size() < 2 ? 0.0 : quantile(gaps, 0.1);
}

flightlog::Column fill_stored_on_change(std::span<const double> time, std::span<const double> values,
                                        double max_gap_s) {
  if (time.size() != values.size()) {
    throw std::invalid_argument("fill_stored_on_change: " + std::to_string(values.size()) + " values for " +
                                std::to_string(time.size()) + " times");
  }
  flightlog::Column out(values.size(), kNaN);
  const double interval = storing_interval_s(time, values);
  std::vector<double> spacing;
  for (std::size_t i = 1; i < time.size(); ++i) {
    if (time[i] > time[i - 1]) spacing.push_back(time[i] - time[i - 1]);
  }
  const double jitter = spacing.empty() ? 0.0 : 0.5 * quantile(spacing, 0.5);
  std::size_t a = values.size();  // the last store seen
  for (std::size_t b = 0; b < values.size(); ++b) {
    if (!std::isfinite(values[b])) continue;
    out[b] = values[b];
    if (a < b) {
      // Known unchanged up to the last row the writer checked it at.
      std::size_t held_to = a;
      bool rows_close = true;
      for (std::size_t k = a + 1; k < b; ++k) {
        rows_close = rows_close && time[k] - time[k - 1] <= max_gap_s;
        if (time[k] >= time[a] + interval - jitter) held_to = k;
      }
      rows_close = rows_close && time[b] - time[b - 1] <= max_gap_s;
      if (rows_close && time[b] - time[held_to] <= max_gap_s) {
        for (std::size_t k = a + 1; k <= held_to; ++k) out[k] = values[a];
        const double span = time[b] - time[held_to];
        for (std::size_t k = held_to + 1; k < b; ++k) {
          const double w = span > 0.0 ? (time[k] - time[held_to]) / span : 1.0;
          out[k] = values[a] + w * (values[b] - values[a]);
        }
      }
    }
    a = b;
  }
  return out;
}

bool decimated_file(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  static const std::set<std::string, std::less<>> kDecimated{".sbd", ".scd", ".mbd", ".mcd",
                                                             ".tbd", ".tcd", ".nbd", ".ncd"};
  return kDecimated.count(ext) != 0;
}

bool any_decimated(const std::vector<std::filesystem::path>& files) {
  return std::any_of(files.begin(), files.end(), [](const std::filesystem::path& f) { return decimated_file(f); });
}

flightlog::FlightLog hold_stored_columns(const flightlog::FlightLog& log, double max_age_s, bool hold_fin) {
  static const std::set<std::string, std::less<>> kHeld{
      "c_heading", "c_fin",         "c_ballast_pumped", "c_battpos",
      "c_pitch",   "m_fin",         "m_roll",           "m_ballast_pumped",
      "m_battpos", "m_depth_state", "m_battery",        "m_coulomb_amphr_total"};
  std::vector<flightlog::Column> columns;
  std::size_t time_index = 0;
  const auto& names = log.column_names();
  const flightlog::Column& time = log.time();
  for (std::size_t c = 0; c < names.size(); ++c) {
    flightlog::Column column = log.column(names[c]);
    if (&log.column(names[c]) == &time) time_index = c;
    if (kHeld.count(names[c]) != 0 && (hold_fin || names[c] != "m_fin")) {
      double held = kNaN, held_at = 0.0;
      for (std::size_t i = 0; i < column.size(); ++i) {
        if (std::isfinite(column[i])) {
          held = column[i];
          held_at = time[i];
        } else if (std::isfinite(held) && time[i] - held_at <= max_age_s) {
          column[i] = held;
        }
      }
    }
    // A heading stored every few seconds: the rows between get it on the shorter arc.
    if (names[c] == "m_heading") column = flightlog::interpolate_angle_rad(time, column, 30.0);
    columns.push_back(std::move(column));
  }
  return flightlog::FlightLog(log.source(), log.metadata(), names, std::move(columns), time_index);
}

}  // namespace glider::diagnose
