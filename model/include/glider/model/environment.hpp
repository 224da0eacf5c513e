// SPDX-License-Identifier: Apache-2.0
#pragma once
// The water the glider flies in: density, temperature, salinity and water
// velocity as functions of depth (a piecewise-linear profile) and time (an
// optional oscillation on top, e.g. a tide or an internal wave). Built at init
// time; sampling it allocates nothing.
#include <limits>
#include <string>
#include <vector>

namespace glider::model {

struct WaterSample {
  double density_kg_m3 = 1025.0;  // in situ
  double temperature_c = 10.0;    // in situ, ITS-90
  double current_east_m_s = 0.0;
  double current_north_m_s = 0.0;
  double vertical_velocity_m_s = 0.0;  // + down (same sign as depth rate)
  // PSS-78; NaN = the water is given by its density alone (no CTD can be
  // simulated in it). Last, so {density, temperature, ...} profiles still read.
  double practical_salinity = std::numeric_limits<double>::quiet_NaN();
  // d(current)/d(depth) where the glider is (1/s, + = the current grows
  // eastward / northward downward): the profile's slope between its nodes,
  // 0 beyond them. A glider crossing it turns (dynamics.hpp).
  double current_shear_east_per_s = 0.0;
  double current_shear_north_per_s = 0.0;
};

// Sea pressure [dbar] at a depth, as the water column and the SIL's CTD use
// it: hydrostatic with a fixed 1025 kg/m^3 and 9.81 m/s^2 (1.0055 dbar/m).
// The column's own density changes the true figure by < 2 % (Baltic to open
// ocean), which moves TEOS-10 density by < 0.01 kg/m^3 over glider depths;
// what matters is that the simulated water and the logged pressure agree.
constexpr double sea_pressure_dbar(double depth_m) { return depth_m * (1025.0 * 9.81 * 1e-4); }

struct ProfileNode {
  double depth_m = 0.0;
  WaterSample water;
};

// A sinusoidal velocity oscillation, the same at all depths:
// amplitude * sin(2 pi t / period + phase).
struct Oscillation {
  double period_s = 0.0;  // 0 = none
  double phase_rad = 0.0;
  double east_m_s = 0.0;
  double north_m_s = 0.0;
  double vertical_m_s = 0.0;
};

class WaterColumn {
 public:
  // Uniform, still water.
  explicit WaterColumn(double density_kg_m3 = 1025.0, double temperature_c = 10.0);
  // Nodes sorted by increasing depth (throws std::invalid_argument if not,
  // or if empty); values are clamped beyond the first and last node.
  // Salinity at every node makes a TEOS-10 column: its density is not taken
  // from the nodes but computed, at every depth, from the interpolated
  // temperature and salinity at sea_pressure_dbar(depth) (the nodes' density
  // is overwritten with that value), so the density the vehicle feels is the
  // one a CTD in the same water measures. Salinity at some nodes only, or
  // T, S, p outside TEOS-10's range, throws std::invalid_argument.
  WaterColumn(std::vector<ProfileNode> nodes, Oscillation oscillation);

  WaterSample at(double depth_m, double time_s) const;
  bool has_salinity() const { return teos10_; }

  const std::vector<ProfileNode>& nodes() const { return nodes_; }
  const Oscillation& oscillation() const { return oscillation_; }

 private:
  std::vector<ProfileNode> nodes_;
  Oscillation oscillation_;
  bool teos10_ = false;
};

struct Environment {
  WaterColumn water{};
  double gravity_m_s2 = 9.81;
};

// Uniform still water of the given density.
inline Environment still_water(double density_kg_m3 = 1025.0) { return Environment{WaterColumn(density_kg_m3)}; }

}  // namespace glider::model
