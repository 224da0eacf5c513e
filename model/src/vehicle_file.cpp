#include "glider/model/vehicle_file.hpp"

#include <charconv>

#include "glider/config/toml_document.hpp"

namespace glider::model {
namespace {

using config::TomlDocument;

// One table of the key <-> field mapping, shared by the reader and the
// metadata writer so the two can never disagree.
template <typename Visitor>
void visit_numbers(VehicleParams& v, Visitor&& visit) {
  visit("mass.hull_kg", v.hull_mass_kg);
  visit("mass.hull_inertia_kg_m2", v.hull_inertia_kg_m2);
  visit("mass.offset_kg", v.offset.mass_kg);
  visit("mass.offset_x_m", v.offset.x_m);
  visit("mass.offset_z_m", v.offset.z_m);
  visit("hull.diameter_m", v.hull_diameter_m);
  visit("battery.mass_kg", v.battery.mass_kg);
  visit("battery.x_at_zero_m", v.battery.x_at_zero_m);
  visit("battery.z_m", v.battery.z_m);
  visit("battery.travel_min_m", v.battery.travel_min_m);
  visit("battery.travel_max_m", v.battery.travel_max_m);
  visit("battery.rate_m_s", v.battery.rate_m_s);
  visit("ballast.x_m", v.ballast.x_m);
  visit("ballast.z_m", v.ballast.z_m);
  visit("ballast.volume_min_m3", v.ballast.volume_min_m3);
  visit("ballast.volume_max_m3", v.ballast.volume_max_m3);
  visit("ballast.rate_m3_s", v.ballast.rate_m3_s);
  visit("added_mass.x_kg", v.added_mass_x_kg);
  visit("added_mass.z_kg", v.added_mass_z_kg);
  visit("added_mass.inertia_kg_m2", v.added_inertia_kg_m2);
  visit("hydrodynamics.reference_area_m2", v.hydro.reference_area_m2);
  visit("hydrodynamics.cl_alpha", v.hydro.cl_alpha);
  visit("hydrodynamics.cl_alpha_abs_alpha", v.hydro.cl_alpha_abs_alpha);
  visit("hydrodynamics.cd0", v.hydro.cd0);
  visit("hydrodynamics.cd_alpha2", v.hydro.cd_alpha2);
  visit("hydrodynamics.cm0_m", v.hydro.cm0_m);
  visit("hydrodynamics.cm_alpha_m", v.hydro.cm_alpha_m);
  visit("hydrodynamics.cmq_m2", v.hydro.cmq_m2);
  visit("hydrodynamics.crossflow_cn90", v.hydro.crossflow_cn90);
  visit("hydrodynamics.fit_valid_to_rad", v.hydro.fit_valid_to_rad);
  visit("hydrodynamics.crossflow_from_rad", v.hydro.crossflow_from_rad);
  visit("buoyancy.trim_density_kg_m3", v.trim_density_kg_m3);
  visit("buoyancy.offset_kg", v.buoyancy_offset_kg);
}

VehicleParams read(const TomlDocument& doc) {
  VehicleParams v;
  v.name = doc.string("vehicle.name");
  v.description = doc.string_or("vehicle.description", "");
  doc.string_or("vehicle.source", "");  // provenance note, not a parameter
  visit_numbers(v, [&doc](const char* key, double& field) { field = doc.number(key); });
  doc.reject_unknown_keys();
  const std::string problem = validate(v);
  if (!problem.empty()) {
    throw config::ConfigError(doc.source() + ": " + problem);
  }
  return v;
}

std::string format_number(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

}  // namespace

VehicleParams load_vehicle_file(const std::filesystem::path& path) {
  return read(TomlDocument::load(path));
}

VehicleParams parse_vehicle_text(const std::string& text, const std::string& source_name) {
  return read(TomlDocument::parse(text, source_name));
}

std::vector<std::pair<std::string, std::string>> vehicle_metadata(const VehicleParams& v) {
  std::vector<std::pair<std::string, std::string>> out;
  out.emplace_back("vehicle.name", v.name);
  VehicleParams copy = v;
  visit_numbers(copy, [&out](const char* key, double& field) { out.emplace_back(key, format_number(field)); });
  return out;
}

}  // namespace glider::model
