// SPDX-License-Identifier: Apache-2.0
#include "glider/model/environment_file.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "glider/config/toml_document.hpp"
#include "glider/units.hpp"

namespace glider::model {
namespace {

using config::Range;
using config::TomlDocument;

// Physical ranges of the ocean the simulator flies in (value_limits.hpp).
const std::vector<config::KeyRange>& limits() {
  static const std::vector<config::KeyRange> table{
      {"gravity_m_s2", {9.7, 9.9, "m/s^2"}},
      {"profile.depth_m", {0.0, 11000.0, "m"}},
      {"profile.practical_salinity", {0.0, 42.0, "(PSS-78)"}},
      {"profile.density_kg_m3", {900.0, 1100.0, "kg/m^3"}},
      {"profile.temperature_c", {-3.0, 40.0, "degC"}},
      {"profile.current_east_m_s", {-5.0, 5.0, "m/s"}},
      {"profile.current_north_m_s", {-5.0, 5.0, "m/s"}},
      {"profile.vertical_velocity_m_s", {-1.0, 1.0, "m/s"}},
      {"oscillation.period_s", {0.0, 1e7, "s"}},
      {"oscillation.phase_deg", {-360.0, 360.0, "deg"}},
      {"oscillation.east_m_s", {-5.0, 5.0, "m/s"}},
      {"oscillation.north_m_s", {-5.0, 5.0, "m/s"}},
      {"oscillation.vertical_m_s", {-1.0, 1.0, "m/s"}},
  };
  return table;
}

const Range& range_of(std::string_view key) { return config::range_of(limits(), key); }

Environment read(const TomlDocument& doc) {
  Environment env;
  env.gravity_m_s2 = doc.number_or("gravity_m_s2", env.gravity_m_s2, range_of("gravity_m_s2"));
  const std::vector<double> depth = doc.numbers_or_empty("profile.depth_m", range_of("profile.depth_m"));
  if (depth.empty()) doc.fail("profile.depth_m", "the profile needs depth_m = [...] with at least one depth");
  // Each profile column: absent = the default everywhere; else one value per depth.
  auto column = [&](const char* key, double fallback) {
    std::vector<double> values = doc.numbers_or_empty(key, range_of(key));
    // Present but empty is not absent: `practical_salinity = []` would
    // silently drop the TEOS-10 density for the default one.
    if (values.empty() && doc.has(key)) {
      doc.fail(key, "is empty: give one value per depth (" + std::to_string(depth.size()) + "), or leave the key out");
    }
    if (values.empty()) return std::vector<double>(depth.size(), fallback);
    if (values.size() != depth.size()) {
      doc.fail(key, "has " + std::to_string(values.size()) + " values for " + std::to_string(depth.size()) + " depths");
    }
    return values;
  };
  // Salinity makes a TEOS-10 column (environment.hpp): its density follows
  // from T, S and depth, so stating a density as well could only contradict it.
  const bool has_salinity = !doc.numbers_or_empty("profile.practical_salinity").empty();
  if (has_salinity && !doc.numbers_or_empty("profile.density_kg_m3").empty()) {
    doc.fail("profile.density_kg_m3",
             "give density_kg_m3 or practical_salinity, not both (TEOS-10 computes the "
             "density from temperature and salinity)");
  }
  if (has_salinity && doc.numbers_or_empty("profile.temperature_c").empty()) {
    doc.fail("profile.practical_salinity", "needs temperature_c at the same depths");
  }
  const auto salinity = column("profile.practical_salinity", NAN);
  const auto density = column("profile.density_kg_m3", 1025.0);
  const auto temperature = column("profile.temperature_c", 10.0);
  const auto east = column("profile.current_east_m_s", 0.0);
  const auto north = column("profile.current_north_m_s", 0.0);
  const auto vertical = column("profile.vertical_velocity_m_s", 0.0);
  std::vector<ProfileNode> nodes;
  for (std::size_t i = 0; i < depth.size(); ++i) {
    nodes.push_back({depth[i], {density[i], temperature[i], east[i], north[i], vertical[i], salinity[i]}});
  }
  Oscillation o;
  o.period_s = doc.number_or("oscillation.period_s", 0.0, range_of("oscillation.period_s"));
  o.phase_rad = deg_to_rad(doc.number_or("oscillation.phase_deg", 0.0, range_of("oscillation.phase_deg")));
  o.east_m_s = doc.number_or("oscillation.east_m_s", 0.0, range_of("oscillation.east_m_s"));
  o.north_m_s = doc.number_or("oscillation.north_m_s", 0.0, range_of("oscillation.north_m_s"));
  o.vertical_m_s = doc.number_or("oscillation.vertical_m_s", 0.0, range_of("oscillation.vertical_m_s"));
  doc.string_or("description", "");
  doc.reject_unknown_keys();
  try {
    env.water = WaterColumn(std::move(nodes), o);
  } catch (const std::invalid_argument& error) {
    doc.fail("profile.depth_m", error.what());
  }
  return env;
}

}  // namespace

Environment load_environment_file(const std::filesystem::path& path) { return read(TomlDocument::load(path)); }

std::vector<config::KeyRange> environment_file_limits() { return limits(); }

Environment parse_environment_text(const std::string& text, const std::string& source_name) {
  return read(TomlDocument::parse(text, source_name));
}

}  // namespace glider::model
