#pragma once

namespace glider::model {

// The water the glider flies in. Uniform and steady for now: the dynamics
// are written relative to the water, so a uniform steady current only adds
// to the position rates.
struct Environment {
  double density_kg_m3 = 1025.0;
  double gravity_m_s2 = 9.81;
  double current_along_track_m_s = 0.0;  // horizontal, + in the direction of travel
  double vertical_velocity_m_s = 0.0;    // + down (same sign as depth rate)
};

}  // namespace glider::model
