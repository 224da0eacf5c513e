// SPDX-License-Identifier: Apache-2.0
#include "glider/health/glider_dir.hpp"

#include <stdexcept>

#include "glider/diagnose/tool_inputs.hpp"
#include "glider/health/output.hpp"
#include "glider/model/vehicle_file.hpp"

namespace glider::health {

namespace fs = std::filesystem;

NominalChoice nominal_for(const std::string& vehicle_path, const fs::path& glider_dir, const std::string& glider,
                          const std::string& boards_dir) {
  if (!vehicle_path.empty()) return {model::load_vehicle_file(vehicle_path), "file " + vehicle_path};
  if (!glider_dir.empty() && fs::is_regular_file(glider_dir / "vehicle.toml")) {
    const std::string file = (glider_dir / "vehicle.toml").string();
    return {model::load_vehicle_file(file), "file " + file};
  }
  if (!glider.empty()) {
    if (const auto file = diagnose::vehicle_file_of_glider(glider, boards_dir)) {
      return {model::load_vehicle_file(*file), "file " + *file + " (glider '" + glider + "' in gliders.toml)"};
    }
  }
  throw std::runtime_error("no vehicle for glider '" + glider + "': give --vehicle FILE" +
                           (glider_dir.empty() ? std::string() : ", or put " + (glider_dir / "vehicle.toml").string()) +
                           ", or list it in " + boards_dir + "/gliders.toml");
}

GliderDirResult update_glider_dir(const fs::path& glider_dir, const std::string& vehicle_path,
                                  const std::string& boards_dir, double seconds_apart) {
  const fs::path from = glider_dir / "from-glider";
  if (!fs::is_directory(from)) throw std::runtime_error(from.string() + ": no such folder");
  const fs::path out = glider_dir / "health";
  HealthOptions options;
  options.inputs = {from.string()};
  options.state_path = (out / "state.json").string();
  options.seconds_apart = seconds_apart;
  const NominalChoice nominal = nominal_for(vehicle_path, glider_dir, glider_dir.filename().string(), boards_dir);
  options.vehicle = nominal.vehicle;
  options.vehicle_source = nominal.source;
  GliderDirResult result;
  result.run = update_health(options);
  result.plots_ok = write_outputs(out, result.run, nominal.vehicle);
  return result;
}

}  // namespace glider::health
