#pragma once
// The water the glider flies in: density, temperature and water velocity as
// functions of depth (a piecewise-linear profile) and time (an optional
// oscillation on top, e.g. a tide or an internal wave). Built at init time;
// sampling it allocates nothing.
#include <string>
#include <vector>

namespace glider::model {

struct WaterSample {
  double density_kg_m3 = 1025.0;
  double temperature_c = 10.0;
  double current_east_m_s = 0.0;
  double current_north_m_s = 0.0;
  double vertical_velocity_m_s = 0.0;  // + down (same sign as depth rate)
};

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
  WaterColumn(std::vector<ProfileNode> nodes, Oscillation oscillation);

  WaterSample at(double depth_m, double time_s) const;

  const std::vector<ProfileNode>& nodes() const { return nodes_; }
  const Oscillation& oscillation() const { return oscillation_; }

 private:
  std::vector<ProfileNode> nodes_;
  Oscillation oscillation_;
};

struct Environment {
  WaterColumn water{};
  double gravity_m_s2 = 9.81;
};

// Uniform still water of the given density.
inline Environment still_water(double density_kg_m3 = 1025.0) { return Environment{WaterColumn(density_kg_m3)}; }

}  // namespace glider::model
