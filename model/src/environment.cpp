// SPDX-License-Identifier: Apache-2.0
#include "glider/model/environment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "glider/model/seawater.hpp"

namespace glider::model {

namespace {

// In-situ density of water of this temperature and salinity at the depth
// (TEOS-10 with Reference Salinity, as the diagnosis reads a CTD).
double teos10_density(double temperature_c, double practical_salinity, double depth_m) {
  const double p = sea_pressure_dbar(std::max(depth_m, 0.0));
  const double sa = seawater::absolute_salinity(practical_salinity);
  return seawater::density(sa, seawater::conservative_temperature(sa, temperature_c, p), p);
}

}  // namespace

WaterColumn::WaterColumn(double density_kg_m3, double temperature_c)
    : nodes_{ProfileNode{0.0, WaterSample{density_kg_m3, temperature_c, 0.0, 0.0, 0.0, NAN}}} {}

WaterColumn::WaterColumn(std::vector<ProfileNode> nodes, Oscillation oscillation)
    : nodes_(std::move(nodes)), oscillation_(oscillation) {
  if (nodes_.empty()) throw std::invalid_argument("water profile has no nodes");
  for (std::size_t i = 1; i < nodes_.size(); ++i) {
    if (!(nodes_[i].depth_m > nodes_[i - 1].depth_m)) {
      throw std::invalid_argument("water profile depths must increase strictly");
    }
  }
  if (oscillation_.period_s < 0.0) throw std::invalid_argument("oscillation period must not be negative");
  std::size_t with_salinity = 0;
  for (const ProfileNode& node : nodes_) with_salinity += std::isfinite(node.water.practical_salinity) ? 1 : 0;
  if (with_salinity != 0 && with_salinity != nodes_.size()) {
    throw std::invalid_argument("water profile: salinity must be given at every node or at none");
  }
  teos10_ = with_salinity != 0;
  if (!teos10_) return;
  for (ProfileNode& node : nodes_) {
    node.water.density_kg_m3 = teos10_density(node.water.temperature_c, node.water.practical_salinity, node.depth_m);
    if (!std::isfinite(node.water.density_kg_m3)) {
      throw std::invalid_argument("water profile: temperature, salinity and depth outside TEOS-10's range at " +
                                  std::to_string(node.depth_m) + " m");
    }
  }
}

WaterSample WaterColumn::at(double depth_m, double time_s) const {
  WaterSample w;
  if (depth_m <= nodes_.front().depth_m) {
    w = nodes_.front().water;
  } else if (depth_m >= nodes_.back().depth_m) {
    w = nodes_.back().water;
  } else {
    const auto upper = std::upper_bound(nodes_.begin(), nodes_.end(), depth_m,
                                        [](double d, const ProfileNode& n) { return d < n.depth_m; });
    const ProfileNode& b = *upper;
    const ProfileNode& a = *(upper - 1);
    const double f = (depth_m - a.depth_m) / (b.depth_m - a.depth_m);
    auto mix = [f](double x, double y) { return x + f * (y - x); };
    w.density_kg_m3 = mix(a.water.density_kg_m3, b.water.density_kg_m3);
    w.temperature_c = mix(a.water.temperature_c, b.water.temperature_c);
    w.current_east_m_s = mix(a.water.current_east_m_s, b.water.current_east_m_s);
    w.current_north_m_s = mix(a.water.current_north_m_s, b.water.current_north_m_s);
    w.vertical_velocity_m_s = mix(a.water.vertical_velocity_m_s, b.water.vertical_velocity_m_s);
    w.practical_salinity = mix(a.water.practical_salinity, b.water.practical_salinity);
    const double span = b.depth_m - a.depth_m;
    w.current_shear_east_per_s = (b.water.current_east_m_s - a.water.current_east_m_s) / span;
    w.current_shear_north_per_s = (b.water.current_north_m_s - a.water.current_north_m_s) / span;
  }
  // Between and beyond the nodes (where pressure still grows), the density
  // of the water actually there, not a straight line between node densities.
  if (teos10_) w.density_kg_m3 = teos10_density(w.temperature_c, w.practical_salinity, depth_m);
  if (oscillation_.period_s > 0.0) {
    const double s = std::sin(2.0 * std::numbers::pi * time_s / oscillation_.period_s + oscillation_.phase_rad);
    w.current_east_m_s += oscillation_.east_m_s * s;
    w.current_north_m_s += oscillation_.north_m_s * s;
    w.vertical_velocity_m_s += oscillation_.vertical_m_s * s;
  }
  return w;
}

}  // namespace glider::model
