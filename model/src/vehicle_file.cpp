// SPDX-License-Identifier: Apache-2.0
#include "glider/model/vehicle_file.hpp"

#include <charconv>
#include <string_view>

#include "glider/config/toml_document.hpp"

namespace glider::model {
namespace {

using config::TomlDocument;

enum class Need { kRequired, kOptional };

// One table of the key <-> field mapping, shared by the reader and the
// metadata writer so the two can never disagree. Optional keys keep the
// field's default (0 = effect absent) when the file does not set them.
// Ranges: physically possible for a glider of up to a few hundred kg and 2 m
// across (value_limits.hpp); relations between keys are validate()'s.
template <typename Visitor>
void visit_numbers(VehicleParams& v, Visitor&& visit) {
  constexpr Need req = Need::kRequired;
  constexpr Need opt = Need::kOptional;
  visit("mass.hull_kg", v.hull_mass_kg, req, {0.1, 1000.0, "kg"});
  visit("mass.hull_inertia_kg_m2", v.hull_inertia_kg_m2, req, {0.001, 1000.0, "kg m^2"});
  visit("mass.offset_kg", v.offset.mass_kg, req, {0.0, 1000.0, "kg"});
  visit("mass.offset_x_m", v.offset.x_m, req, {-5.0, 5.0, "m"});
  visit("mass.offset_z_m", v.offset.z_m, req, {-1.0, 1.0, "m"});
  visit("hull.diameter_m", v.hull_diameter_m, req, {0.01, 2.0, "m"});
  visit("hull.compressibility_per_pa", v.hull_compressibility_per_pa, opt, {0.0, 1e-8, "1/Pa"});
  visit("hull.thermal_expansion_per_k", v.hull_thermal_expansion_per_k, opt, {-1e-3, 1e-3, "1/K"});
  visit("hull.reference_temperature_c", v.hull_reference_temperature_c, opt, {-5.0, 40.0, "degC"});
  visit("battery.mass_kg", v.battery.mass_kg, req, {0.01, 500.0, "kg"});
  visit("battery.x_at_zero_m", v.battery.x_at_zero_m, req, {-5.0, 5.0, "m"});
  visit("battery.z_m", v.battery.z_m, req, {-1.0, 1.0, "m"});
  visit("battery.travel_min_m", v.battery.travel_min_m, req, {-1.0, 1.0, "m"});
  visit("battery.travel_max_m", v.battery.travel_max_m, req, {-1.0, 1.0, "m"});
  visit("battery.rate_m_s", v.battery.rate_m_s, req, {1e-6, 1.0, "m/s"});
  visit("second_mass.mass_kg", v.second_mass.mass_kg, opt, {0.0, 500.0, "kg"});
  visit("second_mass.x_at_zero_m", v.second_mass.x_at_zero_m, opt, {-5.0, 5.0, "m"});
  visit("second_mass.z_m", v.second_mass.z_m, opt, {-1.0, 1.0, "m"});
  visit("second_mass.travel_min_m", v.second_mass.travel_min_m, opt, {-1.0, 1.0, "m"});
  visit("second_mass.travel_max_m", v.second_mass.travel_max_m, opt, {-1.0, 1.0, "m"});
  visit("second_mass.rate_m_s", v.second_mass.rate_m_s, opt, {0.0, 1.0, "m/s"});
  visit("ballast.x_m", v.ballast.x_m, req, {-5.0, 5.0, "m"});
  visit("ballast.z_m", v.ballast.z_m, req, {-1.0, 1.0, "m"});
  visit("ballast.volume_min_m3", v.ballast.volume_min_m3, req, {-0.1, 0.1, "m^3"});
  visit("ballast.volume_max_m3", v.ballast.volume_max_m3, req, {-0.1, 0.1, "m^3"});
  visit("ballast.rate_m3_s", v.ballast.rate_m3_s, req, {1e-8, 0.01, "m^3/s"});
  visit("ballast.lag_s", v.ballast.lag_s, opt, {0.0, 599.0, "s"});
  visit("added_mass.x_kg", v.added_mass_x_kg, req, {0.0, 1000.0, "kg"});
  visit("added_mass.z_kg", v.added_mass_z_kg, req, {0.0, 1000.0, "kg"});
  visit("added_mass.inertia_kg_m2", v.added_inertia_kg_m2, req, {0.0, 1000.0, "kg m^2"});
  visit("hydrodynamics.reference_area_m2", v.hydro.reference_area_m2, req, {1e-4, 10.0, "m^2"});
  visit("hydrodynamics.cl0", v.hydro.cl0, opt, {-1.0, 1.0, ""});
  visit("hydrodynamics.cl_alpha", v.hydro.cl_alpha, req, {0.0, 100.0, "1/rad"});
  visit("hydrodynamics.cl_alpha_abs_alpha", v.hydro.cl_alpha_abs_alpha, req, {-100.0, 100.0, "1/rad^2"});
  visit("hydrodynamics.cd0", v.hydro.cd0, req, {0.001, 10.0, ""});
  visit("hydrodynamics.cd_alpha2", v.hydro.cd_alpha2, req, {0.0, 1000.0, "1/rad^2"});
  visit("hydrodynamics.cd0_reynolds_exponent", v.hydro.cd0_reynolds_exponent, opt, {0.0, 0.5, ""});
  visit("hydrodynamics.cd0_reference_speed_m_s", v.hydro.cd0_reference_speed_m_s, opt, {0.05, 3.0, "m/s"});
  visit("hydrodynamics.cm0_m", v.hydro.cm0_m, req, {-1.0, 1.0, "m"});
  visit("hydrodynamics.cm_alpha_m", v.hydro.cm_alpha_m, req, {-100.0, 100.0, "m/rad"});
  visit("hydrodynamics.cmq_m2", v.hydro.cmq_m2, req, {-100.0, 0.0, "m^2 s/rad"});
  visit("hydrodynamics.crossflow_cn90", v.hydro.crossflow_cn90, req, {0.0, 100.0, ""});
  visit("hydrodynamics.fit_valid_to_rad", v.hydro.fit_valid_to_rad, req, {0.01, 1.57, "rad"});
  visit("hydrodynamics.crossflow_from_rad", v.hydro.crossflow_from_rad, req, {0.01, 1.57, "rad"});
  visit("hydrodynamics.wing_area_m2", v.hydro.wing_area_m2, opt, {0.0, 10.0, "m^2"});
  visit("hydrodynamics.wing_aspect_ratio", v.hydro.wing_aspect_ratio, opt, {0.0, 50.0, ""});
  visit("hydrodynamics.wing_sweep_rad", v.hydro.wing_sweep_rad, opt, {0.0, 1.4, "rad"});
  visit("hydrodynamics.wing_oswald_efficiency", v.hydro.wing_oswald_efficiency, opt, {0.0, 1.0, ""});
  visit("heading.fin_yaw_gain_per_m", v.heading.fin_yaw_gain_per_m, req, {-10.0, 10.0, "1/m"});
  visit("heading.roll_yaw_gain_per_m", v.heading.roll_yaw_gain_per_m, req, {-10.0, 10.0, "1/m"});
  visit("heading.yaw_time_constant_s", v.heading.yaw_time_constant_s, req, {0.01, 1000.0, "s"});
  visit("heading.roll_offset_rad", v.heading.roll_offset_rad, opt, {-0.5, 0.5, "rad"});
  visit("heading.fin_max_rad", v.heading.fin_max_rad, req, {0.01, 1.57, "rad"});
  visit("heading.fin_rate_rad_s", v.heading.fin_rate_rad_s, req, {0.001, 10.0, "rad/s"});
  visit("heading.fin_delay_s", v.heading.fin_delay_s, opt, {0.0, 60.0, "s"});
  visit("heading.fin_deadband_rad", v.heading.fin_deadband_rad, opt, {0.0, 0.2, "rad"});
  visit("heading.yaw_disturbance_rad_s", v.heading.yaw_disturbance_rad_s, opt, {0.0, 0.1, "rad/s"});
  visit("heading.yaw_disturbance_correlation_s", v.heading.yaw_disturbance_correlation_s, opt, {0.1, 3600.0, "s"});
  visit("buoyancy.trim_density_kg_m3", v.trim_density_kg_m3, req, {900.0, 1100.0, "kg/m^3"});
  visit("buoyancy.offset_kg", v.buoyancy_offset_kg, req, {-10.0, 10.0, "kg"});
}

VehicleParams read(const TomlDocument& doc) {
  VehicleParams v;
  v.name = doc.string("vehicle.name");
  v.description = doc.string_or("vehicle.description", "");
  doc.string_or("vehicle.source", "");  // provenance note, not a parameter
  visit_numbers(v, [&doc](const char* key, double& field, Need need, const config::Range& range) {
    field = need == Need::kRequired ? doc.number(key, range) : doc.number_or(key, field, range);
  });
  v.hydro.cd0_reynolds_exponent_stated = doc.has("hydrodynamics.cd0_reynolds_exponent");
  doc.leave_table("fitted");  // the devices fitted: the firmware's (fw::app::read_fitted_devices)
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

VehicleParams load_vehicle_file(const std::filesystem::path& path) { return read(TomlDocument::load(path)); }

VehicleParams parse_vehicle_text(const std::string& text, const std::string& source_name) {
  return read(TomlDocument::parse(text, source_name));
}

std::vector<std::pair<std::string, std::string>> vehicle_metadata(const VehicleParams& v) {
  // `vehicle.` + the file's dotted key; the [vehicle] table's own keys are
  // not doubled ("vehicle.name", not "vehicle.vehicle.name").
  std::vector<std::pair<std::string, std::string>> out;
  out.emplace_back("vehicle.name", v.name);
  VehicleParams copy = v;
  const bool second = has_second_mass(v);
  const bool wings = has_wings(v);
  const bool exponent_stated = v.hydro.cd0_reynolds_exponent_stated;
  visit_numbers(
      copy, [&out, second, wings, exponent_stated](const char* key, double& field, Need, const config::Range&) {
        if (!second && std::string_view(key).starts_with("second_mass.")) return;
        if (!wings && std::string_view(key).starts_with("hydrodynamics.wing_")) return;
        // Silence is kept (a log's vehicle read back diagnoses as its file
        // would); an exponent set in code is written.
        if (!exponent_stated && field == 0.0 && std::string_view(key) == "hydrodynamics.cd0_reynolds_exponent") return;
        out.emplace_back(std::string("vehicle.") + key, format_number(field));
      });
  return out;
}

namespace {

// TOML text from (dotted key, value) pairs whose tables are contiguous.
std::string toml_text(const std::vector<std::pair<std::string, std::string>>& entries) {
  std::string text;
  std::string table;
  for (const auto& [key, value] : entries) {
    const std::size_t dot = key.rfind('.');
    if (dot == std::string::npos) continue;
    const std::string section = key.substr(0, dot);
    if (section != table) {
      text += (text.empty() ? "[" : "\n[") + section + "]\n";
      table = section;
    }
    const bool is_text = key == "vehicle.name" || key == "vehicle.description" || key == "vehicle.source";
    std::string quoted;
    if (!is_text) {
      quoted = value;
    } else {
      quoted.push_back('"');
      for (char c : value) {
        if (c == '"' || c == '\\') quoted.push_back('\\');
        quoted.push_back(c);
      }
      quoted.push_back('"');
    }
    text += key.substr(dot + 1) + " = " + quoted + "\n";
  }
  return text;
}

}  // namespace

VehicleParams vehicle_from_metadata(const std::vector<std::pair<std::string, std::string>>& entries,
                                    const std::string& source_name) {
  // Through the one reader, so that the same checks apply.
  std::vector<std::pair<std::string, std::string>> keyed;
  for (const auto& [key, value] : entries) keyed.emplace_back(key == "name" ? "vehicle.name" : key, value);
  return parse_vehicle_text(toml_text(keyed), source_name + " (vehicle.* metadata)");
}

std::vector<config::KeyRange> vehicle_file_limits() {
  std::vector<config::KeyRange> out;
  VehicleParams scratch;
  visit_numbers(scratch, [&out](const char* key, double&, Need, const config::Range& range) {
    out.push_back({key, range});
  });
  return out;
}

std::string vehicle_file_text(const VehicleParams& v) {
  std::vector<std::pair<std::string, std::string>> entries;
  for (auto& [key, value] : vehicle_metadata(v)) {
    entries.emplace_back(key == "vehicle.name" ? key : key.substr(8), value);  // drop the "vehicle." prefix
  }
  if (!v.description.empty()) entries.insert(entries.begin() + 1, {"vehicle.description", v.description});
  return toml_text(entries);
}

}  // namespace glider::model
