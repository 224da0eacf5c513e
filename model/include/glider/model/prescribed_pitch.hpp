// SPDX-License-Identifier: Apache-2.0
#pragma once
// The translational half of the vertical-plane dynamics (dynamics.hpp) with
// the pitch PRESCRIBED, for flight-model identification from logs: the
// measured pitch is an input, the depth rate the output (as Merckelbach's
// gliderflight dynamic model does). The two impulse equations are the full
// model's own,
//
//   dP1/dt = F1 - q P3,   dP3/dt = F3 + q P1,
//   P1 = A11 v1 + A13 q,  P3 = A22 v3 + A23 q   (A: dynamics' mass matrix),
//
// with the same mass properties, hydrostatics (compressibility, thermal
// expansion, partial immersion) and flow forces; only the pitch equation is
// replaced by the measurement. The slide's own impulse (b) is neglected: the
// battery moves at ~1 mm/s.
#include <Eigen/Core>
#include <limits>

#include "glider/model/dynamics.hpp"

namespace glider::model {

struct PrescribedPitchInputs {
  double theta_rad = 0.0;         // measured pitch
  double q_rad_s = 0.0;           // its rate
  double pumped_volume_m3 = 0.0;  // the volume really displaced (after any pump lag)
  double battery_pos_m = 0.0;
  double depth_m = 0.0;  // measured depth (hydrostatics)
  double density_kg_m3 = 1025.0;
  double temperature_c = 10.0;
  // sin and cos of theta_rad where the caller has them (a table of a
  // track's stages); NaN: derivative() computes them.
  double sin_theta = std::numeric_limits<double>::quiet_NaN();
  double cos_theta = std::numeric_limits<double>::quiet_NaN();
};

class PrescribedPitchDynamics {
 public:
  using Impulse = Eigen::Vector2d;  // P1, P3 (kg m/s)

  PrescribedPitchDynamics(const VehicleParams& vehicle, double gravity_m_s2 = 9.81);

  // dP/dt.
  Impulse rate(const Impulse& p, const PrescribedPitchInputs& in) const;

  // dP/dt and the depth rate relative to the water together (one evaluation
  // of the masses and of the pitch's sine and cosine): an integrator's stage.
  struct Derivative {
    Impulse p_dot;
    double depth_rate_m_s = 0.0;
  };
  Derivative derivative(const Impulse& p, const PrescribedPitchInputs& in) const;
  // The same stage for a flight that keeps its own skin-friction anchors
  // (`friction`, from skin_friction()): several flights flown side by side
  // through the same stages, each the same bits as flown alone (their
  // stages' independent chains of operations then overlap in the core).
  Derivative derivative(const Impulse& p, const PrescribedPitchInputs& in, const SkinFrictionFactor& friction) const;
  // A skin-friction state for one flight, without anchors (as start_flight()
  // leaves this object's own).
  SkinFrictionFactor skin_friction() const {
    SkinFrictionFactor fresh = skin_friction_;
    fresh.restart();
    return fresh;
  }

  // Body-frame velocities relative to the water (v1, v3) from the impulses.
  Eigen::Vector2d velocities(const Impulse& p, const PrescribedPitchInputs& in) const;
  Impulse impulse(double v1, double v3, const PrescribedPitchInputs& in) const;

  // Depth rate relative to the water (+ down) for the impulses.
  double depth_rate_m_s(const Impulse& p, const PrescribedPitchInputs& in) const;

  // Net weight in water (kg, + heavy) for the inputs.
  double net_buoyancy_kg(const PrescribedPitchInputs& in) const;

  // Call at a flight's first stage: the skin friction's anchors
  // (SkinFrictionFactor) then come from this flight's own speeds, never from
  // a flight flown before it with the same object, so a flight's bits are a
  // function of its start state and inputs alone (a remembered flight and a
  // recomputed one are the same bits, whatever was flown in between).
  void start_flight() const { skin_friction_.restart(); }

  const GliderDynamics& dynamics() const { return dynamics_; }

 private:
  GliderDynamics dynamics_;           // its environment carries only the gravity
  PolarSlopes slopes_;                // of the vehicle's polar, once (hydrodynamics.hpp)
  SkinFrictionFactor skin_friction_;  // the drag's Reynolds term without a pow per stage
  // What a stage needs of its inputs alone (masses, net weight, the pitch's
  // sine and cosine), kept for the last inputs: RK4's two middle stages share
  // them, and a step's last stage is usually the next step's first. The same
  // expressions on the same inputs, so the same bits; a cache per object
  // (one object per flight, never shared between threads).
  struct StageInputs {
    bool valid = false;
    PrescribedPitchInputs in;
    double a11 = 0.0, a33 = 0.0, a13 = 0.0, a23 = 0.0;  // translational mass (A(0,0), A(1,1), A(0,2), A(1,2))
    double net_kg = 0.0;
  };
  mutable StageInputs stage_;
  // The pitch's sine and cosine, for the last pitch: a step's first stage
  // has the pitch of the last step's last stage (the same Hermite value) even
  // where its other inputs differ in the last bit (the lagged ballast's
  // m3 -> cc -> m3), and a sincos is a tenth of a diagnosis.
  struct Pitch {
    bool valid = false;
    double theta_rad = 0.0, sin_theta = 0.0, cos_theta = 1.0;
  };
  mutable Pitch pitch_;
};

}  // namespace glider::model
