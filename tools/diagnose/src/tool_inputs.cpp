// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/tool_inputs.hpp"

#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>

#include "glider/model/vehicle_file.hpp"

namespace glider::diagnose {

NominalVehicle nominal_vehicle(const std::string& vehicle_path, const flightlog::FlightLog& log,
                               const std::string& log_path, const std::string& default_vehicle) {
  NominalVehicle v;
  const auto metadata = log.vehicle_metadata();
  if (!vehicle_path.empty()) {
    v.params = model::load_vehicle_file(vehicle_path);
    v.source = "file " + vehicle_path + (metadata.empty() ? "" : "; the log's vehicle metadata is not used");
  } else if (!metadata.empty()) {
    std::vector<std::pair<std::string, std::string>> entries;
    for (const auto& m : metadata) entries.emplace_back(m.key, m.value);
    v.params = model::vehicle_from_metadata(entries, log_path);
    v.source = "the log's vehicle.* metadata";
  } else if (!default_vehicle.empty()) {
    v.params = model::load_vehicle_file(default_vehicle);
    v.source =
        "default vehicle " + std::filesystem::path(default_vehicle).filename().string() + " (the log states none)";
  } else {
    throw std::runtime_error("no vehicle: give --vehicle FILE (the log has no vehicle.* metadata)");
  }
  return v;
}

std::vector<Effect> depth_rate_effects(const std::vector<std::string>& ids) {
  std::vector<Effect> effects;
  for (const std::string& id : ids) {
    bool known = false;
    for (std::size_t i = 0; i < kEffectCount; ++i) {
      const Effect e = effect_from_index(i);
      if (id == info(e).id && e != Effect::kPitchTrimOffset) {
        effects.push_back(e);
        known = true;
      }
    }
    if (!known) throw std::invalid_argument("--fit: '" + id + "' is not a depth-rate effect id");
  }
  return effects;
}

std::vector<std::pair<std::string, std::string>> column_renames(const std::vector<std::string>& renames) {
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const std::string& r : renames) {
    const std::size_t eq = r.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == r.size()) {
      throw std::invalid_argument("--rename wants FROM=TO, got '" + r + "'");
    }
    pairs.emplace_back(r.substr(0, eq), r.substr(eq + 1));
  }
  return pairs;
}

}  // namespace glider::diagnose
