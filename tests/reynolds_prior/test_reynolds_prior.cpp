// SPDX-License-Identifier: Apache-2.0
// Which skin-friction Reynolds exponent a diagnosis flies, decided once
// (diagnose.hpp: drag_reynolds_exponent_for, called by diagnose() itself):
// asked > stated by the vehicle file (0 included) > the prior for a silent
// file. Before, the choice was the callers' (glider-diagnose, the DVL
// protocol, Python), a stated 0 was taken for silence, and the library's
// other callers (the deployment view, health) flew 0 for a silent file.
#include <CppUTest/TestHarness.h>

#include <string>
#include <utility>
#include <vector>

#include "glider/diagnose/deployment_diagnosis.hpp"
#include "glider/diagnose/diagnose.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/vehicle_file.hpp"

namespace diagnose = glider::diagnose;
namespace model = glider::model;

namespace {

const char* const kShallow = GLIDER_SOURCE_DIR "/boards/vehicles/slocum_shallow.toml";

model::VehicleParams shallow() { return model::load_vehicle_file(kShallow); }

// slocum_shallow.toml with `hydrodynamics.cd0_reynolds_exponent = n` added.
model::VehicleParams shallow_stating(double n) {
  std::string text = model::vehicle_file_text(shallow());
  const std::string table = "[hydrodynamics]\n";
  text.insert(text.find(table) + table.size(), "cd0_reynolds_exponent = " + std::to_string(n) + "\n");
  return model::parse_vehicle_text(text, "stating.toml");
}

// The vehicle read back from the metadata a log would carry.
model::VehicleParams through_metadata(const model::VehicleParams& v) {
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& [key, value] : model::vehicle_metadata(v)) entries.emplace_back(key.substr(8), value);
  return model::vehicle_from_metadata(entries, "log.csv");
}

}  // namespace

TEST_GROUP(DiagnoseReynoldsPrior){};

TEST(DiagnoseReynoldsPrior, StatedIncludingZeroElseThePrior) {
  const double prior = diagnose::kDragReynoldsExponentPrior;
  CHECK_FALSE(shallow().hydro.cd0_reynolds_exponent_stated);
  DOUBLES_EQUAL(prior, diagnose::drag_reynolds_exponent_for(shallow(), std::nullopt), 0.0);
  // A file that states 0 means it: the model before the key, not the prior.
  CHECK_TRUE(shallow_stating(0.0).hydro.cd0_reynolds_exponent_stated);
  DOUBLES_EQUAL(0.0, diagnose::drag_reynolds_exponent_for(shallow_stating(0.0), std::nullopt), 0.0);
  DOUBLES_EQUAL(0.15, diagnose::drag_reynolds_exponent_for(shallow_stating(0.15), std::nullopt), 0.0);
  // Asked for (--drag-reynolds-exponent, Python's drag_reynolds_exponent=) wins; 0 switches the prior off.
  DOUBLES_EQUAL(0.0, diagnose::drag_reynolds_exponent_for(shallow(), 0.0), 0.0);
  DOUBLES_EQUAL(0.2, diagnose::drag_reynolds_exponent_for(shallow_stating(0.0), 0.2), 0.0);
  // Set in code (no file): a non-zero exponent counts as stated.
  model::VehicleParams coded = shallow();
  coded.hydro.cd0_reynolds_exponent = 0.05;
  DOUBLES_EQUAL(0.05, diagnose::drag_reynolds_exponent_for(coded, std::nullopt), 0.0);
}

TEST(DiagnoseReynoldsPrior, TheDiagnosedVehicleStatesWhatItFlew) {
  diagnose::Diagnosis d;
  d.drag_reynolds_exponent = 0.0;  // --drag-reynolds-exponent 0 on a silent file
  const model::VehicleParams flown = diagnose::diagnosed_nominal(shallow(), d);
  const model::VehicleParams back = model::parse_vehicle_text(model::vehicle_file_text(flown), "extended.toml");
  DOUBLES_EQUAL(0.0, diagnose::drag_reynolds_exponent_for(back, std::nullopt), 0.0);
}

TEST(DiagnoseReynoldsPrior, ALogsMetadataKeepsSilenceAndStatement) {
  // A real log converted with a silent vehicle file diagnoses as that file does (the prior) ...
  const model::VehicleParams silent = through_metadata(shallow());
  CHECK_FALSE(silent.hydro.cd0_reynolds_exponent_stated);
  DOUBLES_EQUAL(diagnose::kDragReynoldsExponentPrior, diagnose::drag_reynolds_exponent_for(silent, std::nullopt), 0.0);
  // ... and a stated 0 (a SIL log: the exponent the SIL flew) stays stated.
  model::VehicleParams sil = shallow();
  sil.hydro.cd0_reynolds_exponent_stated = true;
  const model::VehicleParams back = through_metadata(sil);
  CHECK_TRUE(back.hydro.cd0_reynolds_exponent_stated);
  DOUBLES_EQUAL(0.0, diagnose::drag_reynolds_exponent_for(back, std::nullopt), 0.0);
}

// The library's callers that do not ask (the deployment view, health)
// fly what glider-diagnose flies: comet-2016 (a real log, no vehicle
// metadata) against the silent slocum_shallow.toml, its drag alone.
TEST(DiagnoseReynoldsPrior, EveryLibraryCallerFliesTheSameRule) {
  const glider::flightlog::FlightLog log =
      glider::flightlog::read_flight_log(GLIDER_SOURCE_DIR "/tests/data/real/comet-2016-174-05.csv");
  diagnose::DiagnoseOptions options;
  options.model = diagnose::FlightModelKind::kSteady;  // the rule, not the model, is under test: the fast one
  options.fit_only = {diagnose::Effect::kDragChange};
  const diagnose::Observations obs = diagnose::prepare_observations(log);
  const diagnose::Diagnosis silent = diagnose::diagnose(shallow(), obs, options);
  DOUBLES_EQUAL(diagnose::kDragReynoldsExponentPrior, silent.drag_reynolds_exponent, 0.0);
  const diagnose::Diagnosis stated0 = diagnose::diagnose(shallow_stating(0.0), obs, options);
  DOUBLES_EQUAL(0.0, stated0.drag_reynolds_exponent, 0.0);
  CHECK_TEXT(silent.findings.front().value != stated0.findings.front().value, "the prior must change the drag");

  diagnose::DeploymentOptions deployment;
  deployment.diagnose = options;
  deployment.effects = {diagnose::Effect::kDragChange};
  std::vector<diagnose::SegmentInput> segments(1);
  segments[0].name = "comet-2016";
  segments[0].observations = obs;
  const diagnose::DeploymentDiagnosis view = diagnose::diagnose_deployment(shallow(), segments, deployment);
  CHECK_TRUE(view.segments.at(0).fixed.has_value());
  DOUBLES_EQUAL(diagnose::kDragReynoldsExponentPrior, view.segments[0].fixed->drag_reynolds_exponent, 0.0);
  DOUBLES_EQUAL(silent.findings.front().value, view.segments[0].fixed->findings.front().value, 0.0);
}
