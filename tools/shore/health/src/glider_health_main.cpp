// SPDX-License-Identifier: Apache-2.0
// glider-health: a glider's flight health from its data, one surfacing at a
// time (docs/health.md): each effect's value, interval and shape over the
// deployment, and the alerts a pilot can act on.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/health/glider_dir.hpp"
#include "glider/health/output.hpp"

namespace {
namespace fs = std::filesystem;
using namespace glider::health;

// A vehicle file that cannot fly what the glider flew is a wrong input,
// not the glider's health: refused naming the vehicle and the file.
std::string vehicle_refusal(const HealthRun& run) {
  for (const SegmentMeasurement& m : run.segments) {
    if (m.why.find("cannot judge: the vehicle ") != std::string::npos) return m.why;
  }
  return {};
}
}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-health", "A glider's flight health at each surfacing, from its data (incremental)");
  CLI::App& app = tool.app();
  std::vector<std::string> inputs;
  std::vector<fs::path> cache_dirs;
  std::string state_path, report_dir, vehicle_path, glider_dir;
  bool json = false;
  double hours_apart = 0.0;
  app.add_option("INPUTS", inputs, "the glider's files: Slocum files, folders, globs, or flight-log CSVs");
  app.add_option("--glider-dir", glider_dir,
                 "the shore's ROOT/GLIDER: reads from-glider/, writes health/ (state.json, health.json, plots/, "
                 "vehicle.toml)");
  app.add_option("--state", state_path, "the incremental state file (default with --glider-dir: health/state.json)");
  app.add_option("--report", report_dir, "write health.json, vehicle.toml and plots/EFFECT.png here");
  app.add_option("--vehicle", vehicle_path,
                 "the nominal vehicle file (else GLIDER_DIR/vehicle.toml, else gliders.toml)")
      ->check(CLI::ExistingFile);
  app.add_option("--cache", cache_dirs, "sensor-list cache directory for binary files");
  tool.add_number("--hours-apart", hours_apart, {0.0, 24.0 * 365.0, "h"},
                  "logs whose clock starts at 0 (SIL) are placed this many hours apart, in the order found");
  tool.add_json_flag(json);
  return tool.run(argc, argv, [&]() -> int {
    if (glider_dir.empty() == inputs.empty()) {
      return tool.fail(glider::cli::kUsage, "give the glider's files, or --glider-dir ROOT/GLIDER (not both)");
    }
    HealthRun run;
    try {
      if (!glider_dir.empty()) {
        if (!state_path.empty() || !report_dir.empty()) {
          return tool.fail(glider::cli::kUsage, "--glider-dir writes health/ itself: no --state or --report");
        }
        const GliderDirResult r =
            update_glider_dir(glider_dir, vehicle_path, glider::cli::boards_dir(), hours_apart * 3600.0);
        run = r.run;
      } else {
        HealthOptions options;
        options.inputs = inputs;
        options.cache_dirs = cache_dirs;
        options.state_path = state_path;
        options.seconds_apart = hours_apart * 3600.0;
        std::string glider;
        for (const SegmentFiles& s : find_segments(inputs)) {
          if (auto g = glider_of_file(s.files.front())) {
            glider = *g;
            break;
          }
        }
        const NominalChoice nominal = nominal_for(vehicle_path, {}, glider, glider::cli::boards_dir());
        options.vehicle = nominal.vehicle;
        options.vehicle_source = nominal.source;
        run = update_health(options);
        if (!report_dir.empty() && !write_outputs(report_dir, run, nominal.vehicle)) {
          std::fprintf(stderr, "glider-health: the plots could not be drawn (gnuplot)\n");
        }
      }
    } catch (const BadInput& error) {
      return tool.fail(glider::cli::kError, error.what());
    }
    if (const std::string refusal = vehicle_refusal(run); !refusal.empty()) {
      return tool.fail(glider::cli::kError, refusal);
    }
    std::fputs(json ? health_json(run).c_str() : health_text(run).c_str(), stdout);
    return static_cast<int>(glider::cli::kOk);
  });
}
