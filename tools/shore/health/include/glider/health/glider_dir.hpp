// SPDX-License-Identifier: Apache-2.0
#pragma once
// Health on the shore's layout (docs/comms.md, "Folders"; docs/health.md):
// ROOT/GLIDER/from-glider/ in, ROOT/GLIDER/health/{state.json, health.json,
// vehicle.toml, plots/} out. Used by `glider-health --glider-dir` and by the
// shore after each surfacing (tools/shore/station/after_surfacing.cpp).
#include <filesystem>
#include <string>

#include "glider/health/health.hpp"

namespace glider::health {

// The nominal vehicle of a glider: `vehicle_path` if given, else
// GLIDER_DIR/vehicle.toml if present, else the file boards/gliders.toml
// gives for `glider`. Throws std::runtime_error naming what is missing.
struct NominalChoice {
  model::VehicleParams vehicle;
  std::string source;
};
NominalChoice nominal_for(const std::string& vehicle_path, const std::filesystem::path& glider_dir,
                          const std::string& glider, const std::string& boards_dir);

struct GliderDirResult {
  HealthRun run;
  bool plots_ok = true;
};

// One update of ROOT/GLIDER: reads from-glider/, writes health/. Throws
// BadInput or std::runtime_error (no vehicle, nothing readable).
GliderDirResult update_glider_dir(const std::filesystem::path& glider_dir, const std::string& vehicle_path,
                                  const std::string& boards_dir, double seconds_apart = 0.0);

}  // namespace glider::health
