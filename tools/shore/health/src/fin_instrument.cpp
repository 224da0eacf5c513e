// SPDX-License-Identifier: Apache-2.0
#include "glider/health/fin_instrument.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace glider::health {

namespace {

constexpr double kUnderWaterM = 2.0;
constexpr double kSaturationRad = 15.0 * std::numbers::pi / 180.0;
constexpr std::array<double, 3> kLagFactors = {1.0, 1.5, 2.0};
constexpr std::size_t kFeatures = 2 + 2 * kLagFactors.size();
constexpr std::size_t kMinRows = 10 * kFeatures;

const flightlog::Column& required(const flightlog::FlightLog& log, const char* name) {
  const flightlog::Column* c = log.find(name);
  if (c == nullptr) {
    throw std::runtime_error(log.source() + ": the fin's instrument needs column " + name + ", which it lacks");
  }
  return *c;
}

double wrapped(double rad) { return std::remainder(rad, 2.0 * std::numbers::pi); }

// At each row, the command of now less the heading at the last row at or
// before lag seconds ago (NaN before the log's start or where either is
// missing): the turn the autopilot is asked for, from a heading the random
// yaw of now has not yet moved.
std::vector<double> command_from_lagged_heading(const flightlog::Column& time, const flightlog::Column& heading,
                                                const flightlog::Column& command, double lag) {
  std::vector<double> error(time.size(), std::nan(""));
  std::size_t j = 0;
  double last = std::nan("");
  for (std::size_t i = 0; i < time.size(); ++i) {
    for (; j < time.size() && time[j] <= time[i] - lag; ++j) {
      if (std::isfinite(heading[j])) last = heading[j];
    }
    if (std::isfinite(last) && std::isfinite(command[i])) error[i] = wrapped(command[i] - last);
  }
  return error;
}

}  // namespace

flightlog::FlightLog with_fin_on_lagged_heading(const flightlog::FlightLog& log, double lag_s) {
  const flightlog::Column& time = log.time();
  const flightlog::Column& fin = required(log, "m_fin");
  const flightlog::Column& depth = required(log, "m_depth");
  const flightlog::Column& pitch = required(log, "m_pitch");
  const flightlog::Column& heading = required(log, "m_heading");
  const flightlog::Column& command = required(log, "c_heading");
  std::vector<std::vector<double>> lagged;
  lagged.reserve(kLagFactors.size());
  for (double factor : kLagFactors) {
    lagged.push_back(command_from_lagged_heading(time, heading, command, factor * lag_s));
  }

  // The glide's sign at every row: m_pitch's last reading (a decimated file
  // stores it every few seconds; a row between its readings must still be
  // projected, or it keeps the logged fin the projection is to replace).
  std::vector<double> glide(time.size(), std::nan(""));
  double last_pitch = std::nan("");
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (std::isfinite(pitch[i])) last_pitch = pitch[i];
    if (std::isfinite(last_pitch)) glide[i] = last_pitch < 0.0 ? -1.0 : 1.0;
  }

  // The instruments of row i; false where one is not defined.
  using Vector = Eigen::Matrix<double, kFeatures, 1>;
  const auto features = [&](std::size_t i, Vector& x) {
    if (!std::isfinite(glide[i])) return false;
    x(0) = 1.0;
    x(1) = glide[i];  // a roll offset's yaw reverses between dives and climbs
    for (std::size_t k = 0; k < lagged.size(); ++k) {
      const double e = lagged[k][i];
      if (!std::isfinite(e)) return false;
      x(static_cast<Eigen::Index>(2 + 2 * k)) = e;
      x(static_cast<Eigen::Index>(3 + 2 * k)) = std::clamp(e, -kSaturationRad, kSaturationRad);
    }
    return true;
  };

  Eigen::Matrix<double, kFeatures, kFeatures> normal = Eigen::Matrix<double, kFeatures, kFeatures>::Zero();
  Vector moment = Vector::Zero();
  Vector x;
  std::size_t rows = 0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (!(depth[i] > kUnderWaterM) || !std::isfinite(fin[i]) || !features(i, x)) continue;
    normal += x * x.transpose();
    moment += x * fin[i];
    ++rows;
  }
  if (rows < kMinRows) {
    throw std::runtime_error(log.source() + ": " + std::to_string(rows) +
                             " rows under water with the fin and the lagged heading, at least " +
                             std::to_string(kMinRows) + " needed to project the fin on them");
  }
  const Vector coefficients = normal.completeOrthogonalDecomposition().solve(moment);

  flightlog::Column projected = fin;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (std::isfinite(fin[i]) && features(i, x)) projected[i] = coefficients.dot(x);
  }
  std::vector<flightlog::Column> columns;
  std::size_t time_index = 0;
  const auto& names = log.column_names();
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (&log.column(names[c]) == &time) time_index = c;
    columns.push_back(names[c] == "m_fin" ? projected : log.column(names[c]));
  }
  return flightlog::FlightLog(log.source(), log.metadata(), names, std::move(columns), time_index);
}

}  // namespace glider::health
