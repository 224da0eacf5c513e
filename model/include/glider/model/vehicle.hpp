// SPDX-License-Identifier: Apache-2.0
#pragma once
// Vehicle parameters of the vertical-plane Leonard-Graver glider model, in SI
// units. Body frame: origin at the centre of buoyancy (CB), x forward along the
// hull, z down when level (Graver et al. 2003, paper 000, Fig. 5).
// The file format that fills this struct is documented in boards/README.md.
#include <string>

namespace glider::model {

struct PointMass {
  double mass_kg = 0.0;
  double x_m = 0.0;
  double z_m = 0.0;
};

// The pitch battery: a point mass sliding along x, driven by a position servo.
struct SlidingMass {
  double mass_kg = 0.0;
  double x_at_zero_m = 0.0;  // x of the mass when the slide reads 0
  double z_m = 0.0;
  double travel_min_m = 0.0;  // slide position limits (m_battpos / 39.37)
  double travel_max_m = 0.0;
  double rate_m_s = 0.0;  // slide speed
};

// The buoyancy engine: pumped volume at a point of the body (SLOCUM: nose).
// Positive pumped volume = water out = more buoyant (Slocum's sign).
struct BuoyancyEngine {
  double x_m = 0.0;
  double z_m = 0.0;
  double volume_min_m3 = 0.0;
  double volume_max_m3 = 0.0;
  double rate_m3_s = 0.0;
  // The displaced volume follows the pump's reported position (m_ballast_pumped)
  // with this first-order time constant (paper 003's ballast-to-buoyancy
  // dynamics; the diagnosis's pump_lag). 0 = no lag.
  double lag_s = 0.0;
};

// Quasi-steady hydrodynamics, coefficients by the reference (frontal) area:
// L = q A C_L(a), D = q A C_D(a), M = q A C_M(a) + damping, q = rho V^2 / 2.
struct Hydrodynamics {
  double reference_area_m2 = 0.0;
  double cl0 = 0.0;  // C_L = cl0 + cl_alpha a + cl_alpha_abs_alpha a|a|
  double cl_alpha = 0.0;
  double cl_alpha_abs_alpha = 0.0;
  double cd0 = 0.0;  // C_D = cd0 + cd_alpha2 a^2
  double cd_alpha2 = 0.0;
  // Skin friction that falls with the Reynolds number: cd0 holds at the speed
  // it was measured at (cd0_reference_speed_m_s) and scales as
  // (V / V_ref)^-n elsewhere (hydrodynamics.hpp: skin_friction_factor). A
  // turbulent flat plate has C_f = 0.074 Re^-0.2 (Schlichting; ITTC-1957's
  // line, 0.075 / (log10 Re - 2)^2, gives a local slope of -0.24 at a
  // glider's Re ~ 4e5); cd0 also holds pressure drag that does not scale,
  // so n is below that. 0 = the drag of the file at every speed (the model
  // before this key, to the bit).
  double cd0_reynolds_exponent = 0.0;
  // Whether the vehicle file states cd0_reynolds_exponent (0 included): the
  // model flies the field either way; a diagnosis of a file that is silent
  // flies its documented prior instead (diagnose.hpp:
  // drag_reynolds_exponent_for). Kept through vehicle_metadata.
  bool cd0_reynolds_exponent_stated = false;
  double cd0_reference_speed_m_s = 0.35;  // a Slocum's typical speed through water
  double cm0_m = 0.0;                     // viscous moment only: the Munk moment comes
  double cm_alpha_m = 0.0;                //   from the added masses in the dynamics
  double cmq_m2 = 0.0;                    // pitch damping: M_q = rho A V cmq q / 2
  double crossflow_cn90 = 0.0;            // normal-force coefficient broadside (a = 90 deg)
  double fit_valid_to_rad = 0.0;          // the fits above hold up to |a| = this ...
  double crossflow_from_rad = 0.0;        // ... and crossflow alone beyond this
  // Optional wings (area 0 = none): their lift slope and induced drag come
  // from the planform (hydrodynamics.hpp) and add to cl_alpha and cd_alpha2,
  // which are then the hull's alone.
  double wing_area_m2 = 0.0;
  double wing_aspect_ratio = 0.0;
  double wing_sweep_rad = 0.0;  // of the quarter chord
  double wing_oswald_efficiency = 0.0;
};

// The drag scaled as a whole (the zero-lift and the induced parts together):
// how fouling, a forecast's drag draw and its speed correction change it.
inline void scale_drag(Hydrodynamics& hydro, double factor) {
  hydro.cd0 *= factor;
  hydro.cd_alpha2 *= factor;
}

// Heading in the spirit of the vertical-plane model (see dynamics.hpp): the
// yaw rate relaxes with a time constant toward what the rudder (fin) and the
// static roll offset ask for, both proportional to the speed.
struct HeadingModel {
  double fin_yaw_gain_per_m = 0.0;   // yaw rate = gain * V * fin (+ fin turns clockwise)
  double roll_yaw_gain_per_m = 0.0;  // yaw rate = gain * V * a_eff * sin(roll) (a_eff = C_L / cl_alpha)
  double yaw_time_constant_s = 0.0;
  double roll_offset_rad = 0.0;  // static roll (+ starboard wing down)
  double fin_max_rad = 0.0;      // fin servo travel (+-)
  double fin_rate_rad_s = 0.0;   // fin servo speed
  double fin_delay_s = 0.0;      // dead time between a fin command and the servo starting to move
  // The servo moves only to a command farther than this from where the fin
  // is (a position deadband; the comet logs' fins hold inside 0.02-0.045
  // rad, glider-diagnose's fin_deadband). 0 = every command is followed.
  double fin_deadband_rad = 0.0;
  // A random yaw rate the fin and roll do not explain (first-order
  // Gauss-Markov: RMS and correlation time), which the SIL draws; the real
  // comet logs have one (glider-diagnose's heading plane). 0 = none.
  double yaw_disturbance_rad_s = 0.0;
  double yaw_disturbance_correlation_s = 10.0;
};

struct VehicleParams {
  std::string name;
  std::string description;
  double hull_mass_kg = 0.0;        // uniformly distributed: at the CB
  double hull_inertia_kg_m2 = 0.0;  // pitch inertia of the hull mass about the CB
  double hull_diameter_m = 0.0;     // for the surface (partial immersion) model
  // Displaced volume V = V0 (1 - compressibility p + thermal_expansion (T - T0)),
  // p gauge pressure in Pa. Nominal 0 (rigid hull) unless the file says otherwise.
  double hull_compressibility_per_pa = 0.0;
  double hull_thermal_expansion_per_k = 0.0;
  double hull_reference_temperature_c = 10.0;
  PointMass offset;  // fixed trim mass m_w at r_w
  SlidingMass battery;
  // A second moving mass (the IIT Madras lab glider of paper 002 has two);
  // mass 0 = absent.
  SlidingMass second_mass;
  HeadingModel heading;
  BuoyancyEngine ballast;
  double added_mass_x_kg = 0.0;      // m_f1
  double added_mass_z_kg = 0.0;      // m_f3
  double added_inertia_kg_m2 = 0.0;  // J_f2
  Hydrodynamics hydro;
  double trim_density_kg_m3 = 0.0;  // water density at which the net buoyancy below holds
  double buoyancy_offset_kg = 0.0;  // net weight at zero ballast and that density (- = light)
};

bool has_second_mass(const VehicleParams& v);
bool has_wings(const VehicleParams& v);  // hydrodynamics.wing_area_m2 > 0

// Mass of the vehicle at zero pumped volume (hull + offset + moving masses).
double dry_mass_kg(const VehicleParams& v);

// Displaced volume that makes the vehicle weigh buoyancy_offset_kg in water
// of trim_density_kg_m3 at zero pumped volume.
double displaced_volume_m3(const VehicleParams& v);

// Empty string when the parameters are physically usable, else the problem.
std::string validate(const VehicleParams& v);

}  // namespace glider::model
