// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/glide_check.hpp"

#include <cmath>
#include <cstdio>

#include "glider/model/steady_glide.hpp"
#include "glider/units.hpp"

namespace glider::sil {
namespace {

// The size of the net buoyancy does not decide whether a steady glide exists
// at a pitch (only its sign does, and the speed it sets through a Reynolds
// drag): a typical Slocum's +-200 g.
constexpr double kNetBuoyancyKg = 0.2;

// A glide direction is warned about when more than a tenth of its settled
// samples sat at pitches with no steady glide: a stalled branch holds its
// pitch there, a somersaulting vehicle passes through them. Measured over the
// boards' vehicles and missions (docs/sil.md): flyable runs < 0.5 %, stalled
// ones 100 %, somersaults 29-65 %.
constexpr double kWarnShare = 0.1;

void check(const model::Hydrodynamics& hydro, double density_kg_m3, const GlideStats& glides, const char* name,
           int direction, std::vector<std::string>& warnings) {
  if (glides.samples == 0) return;
  std::uint64_t unflyable = 0, seen = 0;
  int median_deg = 0;
  for (std::size_t bin = 0; bin < glides.pitch_histogram_deg.size(); ++bin) {
    const std::uint64_t count = glides.pitch_histogram_deg[bin];
    if (count == 0) continue;
    const int degrees = static_cast<int>(bin) - 90;
    if (seen < glides.samples / 2 && seen + count >= glides.samples / 2) median_deg = degrees;
    seen += count;
    if (!model::steady_glide_for_pitch(hydro, density_kg_m3, deg_to_rad(degrees), direction * kNetBuoyancyKg).glide) {
      unflyable += count;
    }
  }
  const double share = static_cast<double>(unflyable) / static_cast<double>(glides.samples);
  if (share <= kWarnShare) return;
  char text[400];
  std::snprintf(text, sizeof text,
                "%s: %.0f %% of the settled samples at pitches where the vehicle has no steady glide (median "
                "pitch %d deg; its shallowest glide path is %.1f deg): the model flew a stalled branch or "
                "somersaulted, not a flight this vehicle can make - check the mission's %s pitch or battery "
                "position for this vehicle",
                name, 100.0 * share, median_deg, model::min_glide_path_deg(hydro, direction),
                direction > 0 ? "dive" : "climb");
  warnings.emplace_back(text);
}

}  // namespace

std::vector<std::string> unflyable_glide_warnings(const model::Hydrodynamics& hydro, double density_kg_m3,
                                                  const FlightStats& stats) {
  std::vector<std::string> warnings;
  check(hydro, density_kg_m3, stats.dives(), "dives", +1, warnings);
  check(hydro, density_kg_m3, stats.climbs(), "climbs", -1, warnings);
  return warnings;
}

}  // namespace glider::sil
