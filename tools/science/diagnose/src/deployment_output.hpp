// SPDX-License-Identifier: Apache-2.0
#pragma once
// What glider-diagnose-deployment shows: the text summary, the JSON object
// and the report directory (a table per segment, a plot per effect).
#include <nlohmann/json.hpp>
#include <string>

#include "glider/diagnose/deployment_diagnosis.hpp"

namespace glider::diagnose {

void print_deployment(const DeploymentDiagnosis& d, const std::string& vehicle_source);
nlohmann::ordered_json deployment_json(const DeploymentDiagnosis& d, const std::string& vehicle_source);
// Throws std::runtime_error when the plots cannot be rendered.
void write_deployment_report(const std::string& dir, const DeploymentDiagnosis& d, const std::string& vehicle_source);

}  // namespace glider::diagnose
