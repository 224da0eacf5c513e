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
// The water moves uniformly and steadily (Environment); states are relative
// to the water, positions inertial. Simplifications, stated here once:
// - ballast mass change: the pumped water carries no momentum in (it is at
//   rest in the water frame), exact in momentum form;
// - partial immersion at the surface reduces buoyancy only (smoothstep over
//   one hull diameter), it adds no moment;
// - no roll/yaw (vertical plane); heading is kept constant by the simulator.
#include <Eigen/Core>

#include "glider/model/environment.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::model {

using State = Eigen::Matrix<double, 6, 1>;
enum StateIndex : int {
  kX = 0,      // horizontal position along track, m
  kZ = 1,      // depth of the CB, m (+ down)
  kTheta = 2,  // pitch, rad (+ nose up)
  kP1 = 3,     // linear impulse along body x, kg m/s
  kP3 = 4,     // linear impulse along body z
  kPi2 = 5,    // angular impulse about body y (pitch), kg m^2/s
};

// Where the internal masses are at an instant (set by the servos).
struct MassInputs {
  double pumped_volume_m3 = 0.0;  // + = water out = lighter
  double battery_pos_m = 0.0;     // slide position, + forward
  double battery_rate_m_s = 0.0;  // slide speed
};

// Body-frame velocities relative to the water and everything derived.
struct Evaluation {
  double v1 = 0.0, v3 = 0.0, q = 0.0;  // m/s, m/s, rad/s
  double speed_m_s = 0.0;
  double alpha_rad = 0.0;
  double net_buoyancy_kg = 0.0;  // weight minus buoyancy, in kg (+ = heavy)
  double lift_n = 0.0, drag_n = 0.0;
  double gravity_moment_nm = 0.0;  // internal masses' weight about the CB
  double hydro_moment_nm = 0.0;    // viscous moment and pitch damping
  double munk_moment_nm = 0.0;     // -(v x P): (m3 - m1) v1 v3 and coupling
  State state_dot = State::Zero();
};

class GliderDynamics {
 public:
  GliderDynamics(const VehicleParams& vehicle, const Environment& environment);

  Evaluation evaluate(const State& state, const MassInputs& masses) const;
  State derivative(const State& state, const MassInputs& masses) const {
    return evaluate(state, masses).state_dot;
  }

  // Builds the impulse state for given velocities (relative to the water).
  State make_state(double x_m, double z_m, double theta_rad, double v1, double v3, double q,
                   const MassInputs& masses) const;

  // Fraction of the hull volume under water when the CB is at depth z_m.
  double immersed_fraction(double z_m) const;

  // Pitch at which the vehicle hangs at rest (no flow), for initial states.
  double static_pitch_rad(const MassInputs& masses) const;

  const VehicleParams& vehicle() const { return vehicle_; }
  const Environment& environment() const { return environment_; }
  Environment& environment() { return environment_; }

 private:
  struct MassProperties {
    Eigen::Matrix3d a;        // generalized mass matrix
    Eigen::Vector3d b;        // impulse of the moving battery relative to the hull
    double total_kg = 0.0;    // all rigid masses (no added mass)
    double first_x = 0.0;     // sum m x
    double first_z = 0.0;     // sum m z
  };
  MassProperties mass_properties(const MassInputs& masses) const;

  VehicleParams vehicle_;
  Environment environment_;
  double displaced_volume_m3_;
};

}  // namespace glider::model
