// SPDX-License-Identifier: Apache-2.0
#include "glider/model/environment_file.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "glider/config/toml_document.hpp"
#include "glider/units.hpp"

namespace glider::model {
namespace {

using config::TomlDocument;

Environment read(const TomlDocument& doc) {
  Environment env;
  env.gravity_m_s2 = doc.number_or("gravity_m_s2", env.gravity_m_s2);
  const std::vector<double> depth = doc.numbers_or_empty("profile.depth_m");
  if (depth.empty()) doc.fail("profile.depth_m", "the profile needs depth_m = [...] with at least one depth");
  // Each profile column: absent = the default everywhere; else one value per depth.
  auto column = [&](const char* key, double fallback) {
    std::vector<double> values = doc.numbers_or_empty(key);
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
    if (!(density[i] > 900.0 && density[i] < 1100.0)) doc.fail("profile.density_kg_m3", "must be 900..1100");
    if (has_salinity && !(salinity[i] >= 0.0 && salinity[i] <= 42.0)) {
      doc.fail("profile.practical_salinity", "must be 0..42 (PSS-78)");
    }
    nodes.push_back({depth[i], {density[i], temperature[i], east[i], north[i], vertical[i], salinity[i]}});
  }
  Oscillation o;
  o.period_s = doc.number_or("oscillation.period_s", 0.0);
  o.phase_rad = deg_to_rad(doc.number_or("oscillation.phase_deg", 0.0));
  o.east_m_s = doc.number_or("oscillation.east_m_s", 0.0);
  o.north_m_s = doc.number_or("oscillation.north_m_s", 0.0);
  o.vertical_m_s = doc.number_or("oscillation.vertical_m_s", 0.0);
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

Environment parse_environment_text(const std::string& text, const std::string& source_name) {
  return read(TomlDocument::parse(text, source_name));
}

}  // namespace glider::model
