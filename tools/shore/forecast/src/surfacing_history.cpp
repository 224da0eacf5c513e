// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/surfacing_history.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "glider/utc_time.hpp"

namespace glider::forecast {
namespace fs = std::filesystem;
using nlohmann::json;

double parse_utc(const std::string& text, const std::string& where) {
  const utc::Parsed parsed = utc::parse_iso(text);
  if (!parsed.ok) {
    throw std::runtime_error(where + ": '" + text + "' is not a UTC time YYYY-MM-DDTHH:MM:SSZ (" + parsed.problem +
                             ")");
  }
  return parsed.seconds();
}

std::string format_utc(double utc_s) { return utc::format_iso(std::round(utc_s)); }

namespace {

std::optional<double> finite_number(const json& object, const char* key) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_number()) return std::nullopt;
  const double value = object[key].get<double>();
  if (!std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<double> sensor(const json& event, const std::string& name) {
  if (!event.contains("sensors") || !event["sensors"].is_array()) return std::nullopt;
  std::optional<double> value;
  for (const json& s : event["sensors"]) {
    if (s.is_object() && s.value("name", "") == name) value = finite_number(s, "value");
  }
  return value;
}

}  // namespace

Surfacing parse_surfacing(const fs::path& file) {
  const std::string where = file.string();
  std::ifstream in(file);
  if (!in) throw std::runtime_error(where + ": cannot read");
  json event;
  try {
    in >> event;
  } catch (const json::exception& e) {
    throw std::runtime_error(where + ": not JSON (" + std::string(e.what()) + ")");
  }
  if (!event.is_object() || event.value("schema", "") != "glider-shore-surfacing/1") {
    throw std::runtime_error(where + ": schema: expected \"glider-shore-surfacing/1\"");
  }
  Surfacing s;
  s.file = file;
  if (!event.contains("glider") || !event["glider"].is_string() || event["glider"].get<std::string>().empty()) {
    throw std::runtime_error(where + ": glider: missing");
  }
  s.glider = event["glider"].get<std::string>();
  for (const char* key : {"call_start_utc", "call_end_utc"}) {
    if (!event.contains(key) || !event[key].is_string()) throw std::runtime_error(where + ": " + key + ": missing");
  }
  s.call_start_utc_s = parse_utc(event["call_start_utc"].get<std::string>(), where + ": call_start_utc");
  s.call_end_utc_s = parse_utc(event["call_end_utc"].get<std::string>(), where + ": call_end_utc");
  if (s.call_end_utc_s < s.call_start_utc_s) {
    throw std::runtime_error(where + ": call_end_utc is before call_start_utc");
  }
  if (event.contains("glider_time") && event["glider_time"].is_object()) {
    s.mission_time_s = finite_number(event["glider_time"], "mission_time_s").value_or(-1.0);
  }
  auto position = [&](const char* key, std::optional<double>& lat, std::optional<double>& lon) {
    if (!event.contains(key) || event[key].is_null()) return;
    lat = finite_number(event[key], "lat_deg");
    lon = finite_number(event[key], "lon_deg");
    if (lat && lon && (std::fabs(*lat) > 90.0 || std::fabs(*lon) > 180.0)) {
      throw std::runtime_error(where + ": " + key + ": position off the globe");
    }
  };
  position("gps", s.lat_deg, s.lon_deg);
  position("dr", s.dr_lat_deg, s.dr_lon_deg);
  s.water_vx_m_s = sensor(event, "m_water_vx");
  s.water_vy_m_s = sensor(event, "m_water_vy");
  for (const auto* v : {&s.water_vx_m_s, &s.water_vy_m_s}) {
    if (*v && std::fabs(**v) > 5.0) throw std::runtime_error(where + ": m_water_vx/vy beyond 5 m/s");
  }
  if (event.contains("mission") && event["mission"].is_object()) s.mission_name = event["mission"].value("name", "");
  if (event.contains("files_sent") && event["files_sent"].is_array()) {
    for (const json& f : event["files_sent"]) {
      if (f.is_object() && f.value("delivered", false) && f.contains("name") && f["name"].is_string()) {
        s.files_delivered.push_back(f["name"].get<std::string>());
      }
    }
  }
  if (event.contains("reasons") && event["reasons"].is_array()) {
    for (const json& r : event["reasons"]) {
      if (!r.is_string()) continue;
      std::string text = r.get<std::string>();
      s.reasons += (s.reasons.empty() ? "" : "; ") + text;
      std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
      if (text.find("abort") != std::string::npos) s.surfaced_by_abort = true;
    }
  }
  if (event.contains("aborts") && event["aborts"].is_object()) {
    const json& a = event["aborts"];
    if (a.contains("last_cause") && a["last_cause"].is_string())
      s.last_abort_cause = a["last_cause"].get<std::string>();
    if (a.contains("last_details") && a["last_details"].is_string() && !a["last_details"].get<std::string>().empty()) {
      s.last_abort_cause += (s.last_abort_cause.empty() ? "" : ": ") + a["last_details"].get<std::string>();
    }
  }
  return s;
}

std::vector<Surfacing> read_surfacings(const fs::path& glider_dir) {
  std::vector<Surfacing> out;
  const fs::path logs = glider_dir / "logs";
  if (!fs::is_directory(logs)) return out;
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(logs)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.size() > 15 && name[0] != '.' && name.ends_with(".surfacing.json")) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) out.push_back(parse_surfacing(file));
  std::stable_sort(out.begin(), out.end(),
                   [](const Surfacing& a, const Surfacing& b) { return a.call_start_utc_s < b.call_start_utc_s; });
  for (const Surfacing& s : out) {
    if (s.glider != out.front().glider) {
      throw std::runtime_error(s.file.string() + ": glider '" + s.glider + "', but " + out.front().file.string() +
                               " is glider '" + out.front().glider + "': two gliders' events in one folder");
    }
  }
  return out;
}

}  // namespace glider::forecast
