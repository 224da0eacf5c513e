// SPDX-License-Identifier: Apache-2.0
#include "after_surfacing.hpp"

#include <cstdio>
#include <exception>

#include "glider/cli/tool.hpp"
#include "glider/forecast/forecast.hpp"
#include "glider/health/glider_dir.hpp"

namespace glider::shore {
namespace {

std::string health_step(const std::filesystem::path& glider_dir) {
  const health::GliderDirResult r = health::update_glider_dir(glider_dir, {}, cli::boards_dir());
  char text[160];
  std::snprintf(text, sizeof text, "health: %s, %zu segments (%zu measured now, %.2f s)%s",
                r.run.assessment.state.c_str(), r.run.segments.size(), r.run.measured, r.run.cost_s,
                r.plots_ok ? "" : "; plots not drawn (gnuplot)");
  std::string note = text;
  for (const health::Alert& a : r.run.assessment.alerts) note += "; ALERT " + a.id + ": " + a.message;
  return note;
}

}  // namespace

std::vector<std::string> after_surfacing(const std::filesystem::path& glider_dir) noexcept {
  std::vector<std::string> notes;
  try {
    try {
      notes.push_back(health_step(glider_dir));
    } catch (const std::exception& error) {
      notes.push_back(std::string("health: failed: ") + error.what());
    } catch (...) {
      notes.push_back("health: failed: unknown error");
    }
    // After health: the forecast flies the vehicle file health just wrote
    // (health/vehicle.toml). It catches its own errors and says them.
    notes.push_back(forecast::forecast_after_surfacing(glider_dir));
  } catch (...) {
    // Building a note failed (out of memory): nothing more can be said.
  }
  return notes;
}

}  // namespace glider::shore
