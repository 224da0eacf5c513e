// SPDX-License-Identifier: Apache-2.0
// What each vehicle effect does to the nominal vehicle (flight_model.hpp's
// apply): the parts of the vocabulary whose meaning is a convention.
#include <CppUTest/TestHarness.h>

#include <cmath>

#include "glider/diagnose/flight_model.hpp"
#include "glider/model/hydrodynamics.hpp"
#include "glider/model/vehicle_file.hpp"

using namespace glider;

namespace {

model::VehicleParams shallow() {
  return model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_shallow.toml");
}

// The relative volume change a (T - T0) of a vehicle at temperature t.
double expansion(const model::VehicleParams& v, double t) {
  return v.hull_thermal_expansion_per_k * (t - v.hull_reference_temperature_c);
}

diagnose::EffectValues with(diagnose::Effect effect, double value) {
  diagnose::EffectValues x = diagnose::nominal_values();
  x[static_cast<std::size_t>(effect)] = value;
  return x;
}

}  // namespace

TEST_GROUP(DiagnoseEffects){};

TEST(DiagnoseEffects, ThermalExpansionIsAboutTheLogsTemperature) {
  // No nominal expansion: the effect's alone, zero at the log's 14.85 degC,
  // so the buoyancy there stays the nominal's (the offset's to explain).
  const model::VehicleParams v = diagnose::apply(shallow(), with(diagnose::Effect::kThermalExpansion, 2e-4), 14.85);
  DOUBLES_EQUAL(2e-4, v.hull_thermal_expansion_per_k, 0.0);
  DOUBLES_EQUAL(0.0, expansion(v, 14.85), 1e-15);
  // A nominal expansion about its own reference adds to the effect's.
  model::VehicleParams nominal = shallow();
  nominal.hull_thermal_expansion_per_k = 5e-5;
  nominal.hull_reference_temperature_c = 10.0;
  const model::VehicleParams both = diagnose::apply(nominal, with(diagnose::Effect::kThermalExpansion, 1e-4), 15.0);
  for (double t : {5.0, 12.0, 20.0}) {
    DOUBLES_EQUAL(5e-5 * (t - 10.0) + 1e-4 * (t - 15.0), expansion(both, t), 1e-15);
  }
  // Without the effect, or without a temperature in the log, nothing moves.
  DOUBLES_EQUAL(10.0, diagnose::apply(nominal, diagnose::nominal_values(), 15.0).hull_reference_temperature_c, 0.0);
  DOUBLES_EQUAL(
      10.0, diagnose::apply(nominal, with(diagnose::Effect::kThermalExpansion, 1e-4), NAN).hull_reference_temperature_c,
      0.0);
}

TEST(DiagnoseEffects, LiftChangeScalesHullAndWingsAlike) {
  const model::VehicleParams nominal = shallow();
  const model::VehicleParams v = diagnose::apply(nominal, with(diagnose::Effect::kLiftChange, 0.8), NAN);
  DOUBLES_EQUAL(0.8 * model::lift_slope_per_rad(nominal.hydro), model::lift_slope_per_rad(v.hydro), 1e-12);
  // The wings' induced drag follows their lift, as for less wing; the hull's stays.
  DOUBLES_EQUAL(0.8 * model::wing_induced_drag_per_rad2(nominal.hydro), model::wing_induced_drag_per_rad2(v.hydro),
                1e-12);
  DOUBLES_EQUAL(nominal.hydro.cd_alpha2, v.hydro.cd_alpha2, 0.0);
  DOUBLES_EQUAL(nominal.hydro.cd0, v.hydro.cd0, 0.0);
  CHECK_FALSE(diagnose::flyable(with(diagnose::Effect::kLiftChange, 0.0)));
  CHECK_TRUE(diagnose::flyable(with(diagnose::Effect::kLiftChange, 0.8)));
}
