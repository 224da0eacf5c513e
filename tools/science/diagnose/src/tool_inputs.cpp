// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/tool_inputs.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "glider/config/toml_document.hpp"
#include "glider/model/vehicle_file.hpp"

namespace glider::diagnose {

namespace {

// Slocum names every file <glider>-<yyyy>-<ddd>-<mission>-<segment>.
std::optional<std::string> glider_of_slocum_name(const std::string& file_name) {
  static const std::regex kSlocumName(R"(^([A-Za-z][A-Za-z0-9_]*)-[0-9]{4}-[0-9]{1,3}-[0-9]+-[0-9]+)");
  std::smatch m;
  if (std::regex_search(file_name, m, kSlocumName)) return m[1].str();
  return std::nullopt;
}

}  // namespace

std::optional<std::string> glider_named_by(const flightlog::FlightLog& log, const std::string& log_path) {
  // A CSV's "# glider: comet (Slocum shallow, 100 m)": its first word.
  if (const auto glider = log.metadata_value("glider")) {
    std::istringstream words(*glider);
    std::string name;
    if (words >> name) return name;
  }
  // A glider's own files, or a folder of them: the first file's name.
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::is_directory(log_path, error)) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(log_path, error)) names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    for (const std::string& name : names) {
      if (auto glider = glider_of_slocum_name(name)) return glider;
    }
    return std::nullopt;
  }
  return glider_of_slocum_name(fs::path(log_path).filename().string());
}

std::optional<std::string> vehicle_file_of_glider(const std::string& glider, const std::string& boards_dir) {
  namespace fs = std::filesystem;
  const fs::path index = fs::path(boards_dir) / "gliders.toml";
  if (boards_dir.empty() || !fs::is_regular_file(index)) return std::nullopt;
  const auto doc = config::TomlDocument::load(index);
  const std::string key = "gliders." + glider + ".vehicle";
  if (!doc.has(key)) return std::nullopt;
  const fs::path file = fs::path(boards_dir) / doc.string(key);
  if (!fs::is_regular_file(file)) doc.fail(key, "no vehicle file " + file.string());
  return file.string();
}

NominalVehicle nominal_vehicle(const VehicleChoice& choice, const flightlog::FlightLog& log,
                               const std::string& log_path) {
  NominalVehicle v;
  const auto metadata = log.vehicle_metadata();
  if (!choice.vehicle_path.empty()) {
    v.params = model::load_vehicle_file(choice.vehicle_path);
    v.source = "file " + choice.vehicle_path + (metadata.empty() ? "" : "; the log's vehicle metadata is not used");
    return v;
  }
  if (!metadata.empty()) {
    std::vector<std::pair<std::string, std::string>> entries;
    for (const auto& m : metadata) entries.emplace_back(m.key, m.value);
    v.params = model::vehicle_from_metadata(entries, log_path);
    v.source = "the log's vehicle.* metadata";
    return v;
  }
  if (!choice.default_vehicle.empty()) {
    v.params = model::load_vehicle_file(choice.default_vehicle);
    v.source = "--default-vehicle " + std::filesystem::path(choice.default_vehicle).filename().string() +
               " (the log states none)";
    return v;
  }
  // A real glider's log is diagnosed against that glider's vehicle, never a
  // stand-in: WE01's numbers on another glider's log give a wrong answer that
  // reads like a right one.
  const auto glider = glider_named_by(log, log_path);
  if (glider) {
    if (const auto file = vehicle_file_of_glider(*glider, choice.boards_dir)) {
      v.params = model::load_vehicle_file(*file);
      v.source = "file " + *file + " (glider '" + *glider + "' in " + choice.boards_dir + "/gliders.toml)";
      return v;
    }
  }
  throw NoVehicle(log_path + ": no vehicle: the log " +
                  (glider ? "names glider '" + *glider + "', which " + choice.boards_dir + "/gliders.toml does not list"
                          : std::string("names no glider and has no vehicle.* metadata")) +
                  "; give --vehicle FILE (the vehicles are in " + choice.boards_dir + "/vehicles)");
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
