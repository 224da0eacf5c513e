// SPDX-License-Identifier: Apache-2.0
#pragma once
// The heading plane's diagnosis as the `heading` object of glider-diagnose's
// JSON (docs/diagnose/README.md, "Heading plane") and as text.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

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

}  // namespace glider::diagnose
