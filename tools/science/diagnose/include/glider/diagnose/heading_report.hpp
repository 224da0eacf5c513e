// SPDX-License-Identifier: Apache-2.0
#pragma once
// The heading plane's diagnosis as the `heading` object of glider-diagnose's
// JSON (docs/diagnose/README.md, "Heading plane") and as text.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "glider/diagnose/diagnose.hpp"
#include "glider/diagnose/heading_diagnose.hpp"

namespace glider::diagnose {

nlohmann::ordered_json heading_json(const HeadingDiagnosis& d);
// {"available": false, "reason": ...}: the log cannot be diagnosed in this plane.
nlohmann::ordered_json heading_unavailable_json(const std::string& reason);
std::string heading_text(const HeadingDiagnosis& d);

// The heading plane of a log as glider-diagnose and the Python module report
// it: the diagnosis and its `heading` object, or no diagnosis and
// {"available": false, "reason"} when the log cannot be read in this plane.
struct HeadingPlane {
  std::optional<HeadingDiagnosis> diagnosis;
  nlohmann::ordered_json json;
};
HeadingPlane heading_plane(const model::VehicleParams& nominal, const flightlog::FlightLog& log,
                           const HeadingDiagnoseOptions& options = {});

// The vehicle the heading plane flies when the vertical plane diagnosed the
// same log first (glider-diagnose's --plane both, the Python module): the
// vertical findings (drag, lift, ...) applied, so that a vertical change is
// not read as a heading one (a hidden drag read as a roll offset). Not
// diagnosed_nominal's Reynolds prior: flown on logs without a vertical
// finding it grew the roll offsets read (docs/science.md, "The heading plane
// flies the vertical plane's findings").
model::VehicleParams heading_vehicle(const model::VehicleParams& vehicle, const Diagnosis& vertical);

}  // namespace glider::diagnose
