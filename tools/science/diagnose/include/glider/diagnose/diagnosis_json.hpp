// SPDX-License-Identifier: Apache-2.0
#pragma once
// A diagnosis as the JSON object `glider-diagnose --json` prints (and the
// Python module's glider.diagnose() returns): one schema for both.
#include <nlohmann/json.hpp>
#include <string>

#include "glider/diagnose/diagnose.hpp"

namespace glider::diagnose {

nlohmann::ordered_json diagnosis_json(const Diagnosis& d, const std::string& vehicle_source, double wall_s);

}  // namespace glider::diagnose
