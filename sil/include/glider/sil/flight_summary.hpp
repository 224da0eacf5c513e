// SPDX-License-Identifier: Apache-2.0
#pragma once
// glider-sil's machine-readable summary of one run (`--summary-json FILE`).
// The keys are a stable interface (docs/sil-summary.md): campaigns and CI read
// them; add keys, never rename or drop one without bumping "schema".
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "glider/firmware/flight_software.hpp"
#include "glider/firmware/geo.hpp"
#include "glider/sil/scenario.hpp"

namespace glider::sil {

inline constexpr const char* kSummarySchema = "glider-sil-summary/1";

struct SummaryContext {
  std::string mission_file;
  std::string vehicle_file;
  std::uint64_t seed = 0;
  double wall_time_s = 0.0;
  fw::LatLon launch{};                      // the frame the true waypoint distances are measured in
  std::vector<std::string> glide_warnings;  // unflyable_glide_warnings (glide_check.hpp)
};

// complete | aborted | stopped (the runner's time limit ended it first).
const char* result_name(const ScenarioResult& result);

nlohmann::ordered_json flight_summary(const ScenarioResult& result, const fw::FlightSoftwareConfig& config,
                                      const SummaryContext& context);

}  // namespace glider::sil
