// SPDX-License-Identifier: Apache-2.0
#pragma once
// The heading plane's diagnosis as the `heading` object of glider-diagnose's
// JSON (docs/diagnose/README.md, "Heading plane") and as text.
#include <nlohmann/json.hpp>
#include <string>

#include "glider/diagnose/heading_diagnose.hpp"

namespace glider::diagnose {

nlohmann::ordered_json heading_json(const HeadingDiagnosis& d);
// {"available": false, "reason": ...}: the log cannot be diagnosed in this plane.
nlohmann::ordered_json heading_unavailable_json(const std::string& reason);
std::string heading_text(const HeadingDiagnosis& d);

}  // namespace glider::diagnose
