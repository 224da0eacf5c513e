// SPDX-License-Identifier: Apache-2.0
#pragma once
// Vertical-plane Leonard-Graver glider dynamics in momentum (Kirchhoff) form.
//
//   dP/dt = F - Omega x P,   dPi/dt = T - v x P        (P: linear, Pi: angular impulse)
//
// P and Pi are the impulses of the whole system about the CB: hull, fixed
// offset mass, ballast point mass, sliding battery and the added fluid masses.
// With the internal masses on prescribed body-frame paths (the slide and pump
// are position servos) the velocities follow from  [v1 v3 q] = A^-1 (P - b),
// where A is the generalized mass matrix (depends on where the masses are)
// and b the impulse of the masses moving inside the hull. This carries all of
// Graver's coupling terms (000 eqs. 1-5; 003 eqs. 2-16) without having to
// differentiate the servo paths, and a sudden slide start is an impulsive,
// momentum-conserving event, as it physically is.
//
// The water moves (Environment: profiles by depth, oscillation in time); the
// vertical-plane states are relative to the local water, positions inertial.
// Simplifications, stated here once:
// - the water's own acceleration (shear crossed at the glider's depth rate,
//   tides) is not fed back as a force: ~50 kg x 1e-4 m/s^2, negligible
//   against the ~2.5 N of net buoyancy;
// - ballast mass change: the pumped water carries no momentum in (it is at
//   rest in the water frame), exact in momentum form;
// - partial immersion at the surface reduces buoyancy only (smoothstep over
//   one hull diameter), it adds no moment;
// - heading is not a rigid-body degree of freedom here (unlike the 6-DOF
//   model of paper 001): the yaw rate relaxes (first order) toward
//   fin_gain V fin + roll_gain V a_eff sin(roll offset) (+ a random yaw
//   disturbance the SIL may add); the heading also turns by
//   pitch rate x tan(roll offset) / cos(pitch) (Euler's kinematics: a
//   rolled glider's inflection swings its nose sideways), and by
//   -depth rate x d(starboard current)/d(depth) / V crossing a vertical
//   shear of the current (the fin weathervanes it into the water it enters).
//   Roll, sideslip and
//   their coupling back into the vertical plane are neglected; a turning
//   glider keeps the vertical-plane speeds of the straight glide.
#include <array>

#include <Eigen/Core>

#include "glider/model/environment.hpp"
#include "glider/model/hydrodynamics.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::model {

using State = Eigen::Matrix<double, 9, 1>;
enum StateIndex : int {
  kEast = 0,     // position east of the start, m
  kNorth = 1,    // position north of the start, m
  kZ = 2,        // depth of the CB, m (+ down)
  kTheta = 3,    // pitch, rad (+ nose up)
  kP1 = 4,       // linear impulse along body x, kg m/s
  kP3 = 5,       // linear impulse along body z
  kPi2 = 6,      // angular impulse about body y (pitch), kg m^2/s
  kPsi = 7,      // heading, rad (0 north, clockwise; not wrapped)
  kYawRate = 8,  // rad/s
};

// Where the internal masses and the fin are at an instant (set by servos).
struct MassInputs {
  double pumped_volume_m3 = 0.0;  // + = water out = lighter
  double battery_pos_m = 0.0;     // slide position, + forward
  double battery_rate_m_s = 0.0;  // slide speed
  double second_pos_m = 0.0;      // second moving mass, if the vehicle has one
  double second_rate_m_s = 0.0;
  double fin_rad = 0.0;  // rudder angle, + turns clockwise
  // A yaw rate the fin and the roll do not explain (rad/s, added to what
  // they ask for): the random yaw of heading.yaw_disturbance_rad_s, which the
  // SIL draws (not an internal mass: an input of the same kind, set from outside).
  double yaw_disturbance_rad_s = 0.0;
};

// Body-frame velocities relative to the water and everything derived.
struct Evaluation {
  double v1 = 0.0, v3 = 0.0, q = 0.0;  // m/s, m/s, rad/s
  double speed_m_s = 0.0;
  double alpha_rad = 0.0;
  double net_buoyancy_kg = 0.0;  // weight minus buoyancy, in kg (+ = heavy)
  double displaced_volume_m3 = 0.0;
  double horizontal_speed_m_s = 0.0;  // through the water, along the heading
  WaterSample water;
  double lift_n = 0.0, drag_n = 0.0;
  double gravity_moment_nm = 0.0;  // internal masses' weight about the CB
  double hydro_moment_nm = 0.0;    // viscous moment and pitch damping
  double munk_moment_nm = 0.0;     // -(v x P): (m3 - m1) v1 v3 and coupling
  State state_dot = State::Zero();
};

// Lift, drag and viscous moment of the flow relative to the water, and their
// body-frame force components (shared by the full dynamics and the
// prescribed-pitch model of prescribed_pitch.hpp).
struct FlowForces {
  double speed_m_s = 0.0, alpha_rad = 0.0;
  double lift_coefficient = 0.0;
  double lift_n = 0.0, drag_n = 0.0;
  double f1 = 0.0, f3 = 0.0;  // body x and z components of lift + drag
  double moment_nm = 0.0;     // viscous moment (no damping, no Munk)
};
FlowForces flow_forces(const Hydrodynamics& h, double water_density, double v1, double v3);
// The same with the speed |(v1, v3)| given: std::hypot (guarded against
// overflow, and slow) is a fifth of a diagnosis' time, where a plain square
// root of glider speeds loses nothing.
// with_moment false: moment_nm left 0 (the prescribed-pitch model needs no
// moment; the forces are the same bits either way).
FlowForces flow_forces_at_speed(const Hydrodynamics& h, double water_density, double v1, double v3, double speed_m_s,
                                bool with_moment = true);
// The same with the polar's slopes of `h` given (polar_slopes(h)): a flight's
// stages ask with one vehicle.
FlowForces flow_forces_at_speed(const Hydrodynamics& h, const PolarSlopes& slopes, double water_density, double v1,
                                double v3, double speed_m_s, bool with_moment = true);
// ... and with the skin friction's factor at this speed given
// (SkinFrictionFactor; skin_friction_factor(h, speed_m_s) in the others).
FlowForces flow_forces_at_speed(const Hydrodynamics& h, const PolarSlopes& slopes, double water_density, double v1,
                                double v3, double speed_m_s, bool with_moment, double cd0_factor);

// Heading rate (rad/s) per unit of the current's starboard shear (1/s) for a
// glider whose depth grows at depth_rate_m_s, moving at speed_m_s through
// the water. Crossing a vertical shear, the water it enters moves sideways
// against the water it left: its velocity through the water swings by the
// change of the cross current over the speed, and the fin weathervanes the
// nose after it. Slower than 0.1 m/s (surface, inflections) the swing is
// taken at that speed: no flow, no weathervane.
double shear_turn_per_unit(double depth_rate_m_s, double speed_m_s);

class GliderDynamics {
 public:
  struct MassProperties {
    Eigen::Matrix3d a;          // generalized mass matrix
    Eigen::Vector3d b;          // impulse of the moving battery relative to the hull
    double total_kg = 0.0;      // all rigid masses (no added mass)
    double first_x = 0.0;       // sum m x
    double first_z = 0.0;       // sum m z
    Eigen::Matrix3d a_inverse;  // A^-1: impulse to velocities
  };

  // The last mass properties computed, for a caller that evaluates the
  // dynamics many times with the internal masses at rest (the simulator:
  // most integration steps move no servo). Same inputs, same bits: the cache
  // changes no result. One per caller (evaluate() stays const and shareable).
  class MassCache {
   public:
    const MassProperties& get(const GliderDynamics& dynamics, const MassInputs& masses, double water_density);

   private:
    bool valid_ = false;
    MassInputs masses_{};  // fin_rad ignored: it moves no mass
    double water_density_ = 0.0;
    MassProperties value_;
  };

  GliderDynamics(const VehicleParams& vehicle, const Environment& environment);

  // `cache` (optional) holds the last mass properties between calls.
  Evaluation evaluate(double time_s, const State& state, const MassInputs& masses, MassCache* cache = nullptr) const;
  State derivative(double time_s, const State& state, const MassInputs& masses) const {
    return evaluate(time_s, state, masses).state_dot;
  }

  // Builds the state for given velocities (relative to the water), at the
  // origin, heading north, not turning.
  State make_state(double z_m, double theta_rad, double v1, double v3, double q, const MassInputs& masses) const;

  // Fraction of the hull volume under water when the CB is at depth z_m.
  double immersed_fraction(double z_m) const;

  // Displaced volume at a depth in the given water (compressibility,
  // thermal expansion, partial immersion).
  double displaced_volume_m3(double z_m, const WaterSample& water) const;

  // Net weight in water (kg, + heavy) at rest at depth z_m in the given
  // water, with the internal masses where `masses` says.
  double net_buoyancy_kg(double z_m, const WaterSample& water, const MassInputs& masses) const;

  // Pitch at which the vehicle hangs at rest (no flow), for initial states.
  double static_pitch_rad(const MassInputs& masses) const;

  // Masses, first moments and the generalized mass matrix where the internal
  // masses are (the pumped volume weighs -water_density * volume).
  MassProperties mass_properties(const MassInputs& masses, double water_density) const;

  // Only the total and first moments of mass_properties (same bits), without
  // the inertia, the matrix and its inverse: all the prescribed-pitch model
  // needs, evaluated millions of times by a diagnosis.
  struct RigidMasses {
    double total_kg = 0.0, first_x = 0.0, first_z = 0.0;
  };
  RigidMasses rigid_masses(const MassInputs& masses, double water_density) const;

  const VehicleParams& vehicle() const { return vehicle_; }
  const Environment& environment() const { return environment_; }

 private:
  VehicleParams vehicle_;
  Environment environment_;
  double nominal_volume_m3_;
  double sin_roll_offset_;  // constant: the roll term of the yaw rate
  double tan_roll_offset_;  // constant: the pitch rate's share of the heading rate

  struct PointMass {
    double m, x, z;
  };
  // The hull's point masses (offset, pumped volume, battery, second mass) where `masses` puts them.
  std::array<PointMass, 4> point_masses(const MassInputs& masses, double water_density) const;
};

inline GliderDynamics::RigidMasses GliderDynamics::rigid_masses(const MassInputs& masses, double water_density) const {
  // Inline (header): called at every derivative, a call and return here cost
  // up to 7 % of a diagnosis's time where the linker happened to place it
  // (docs/science.md, session 41 speed8); the code is the same.
  // The sums over point_masses(), in its order (so bit for bit the same), without building the array:
  // this runs at every derivative of the diagnosis's prescribed-pitch flights (8 % of a 24 h log's
  // instructions when it went through the array).
  const VehicleParams& v = vehicle_;
  const double ballast_kg = -water_density * masses.pumped_volume_m3;
  const double battery_x_m = v.battery.x_at_zero_m + masses.battery_pos_m;
  const double second_x_m = v.second_mass.x_at_zero_m + masses.second_pos_m;
  RigidMasses r;
  r.total_kg = v.hull_mass_kg + v.offset.mass_kg + ballast_kg + v.battery.mass_kg + v.second_mass.mass_kg;
  r.first_x = 0.0 + v.offset.mass_kg * v.offset.x_m + ballast_kg * v.ballast.x_m + v.battery.mass_kg * battery_x_m +
              v.second_mass.mass_kg * second_x_m;
  r.first_z = 0.0 + v.offset.mass_kg * v.offset.z_m + ballast_kg * v.ballast.z_m + v.battery.mass_kg * v.battery.z_m +
              v.second_mass.mass_kg * v.second_mass.z_m;
  return r;
}

}  // namespace glider::model
