// SPDX-License-Identifier: Apache-2.0
#include "surface_dialog.hpp"

#include <cmath>
#include <cstdlib>
#include <ctime>
#include <regex>

#include "glider/utc_time.hpp"

namespace glider::shore {
namespace {

// "1e+308 secs ago" is how the console says "never measured".
std::optional<double> age_of(const std::string& text) {
  char* end = nullptr;
  const double age = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || !std::isfinite(age) || age < 0.0 || age >= 1e300) return std::nullopt;
  return age;
}

bool to_double(const std::string& text, double& out) {
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0' && std::isfinite(out);
}

const std::regex& fix_regex() {
  // GPS Location:  3310.021 N -11741.800 E measured     64.746 secs ago
  // GPS Invalid :  3310.066 N -11741.666 E measured    154.415 secs ago
  // DR  Location:  3310.021 N -11741.800 E measured     60.812 secs ago
  static const std::regex re(
      R"(^\s*(GPS Location|GPS TooFar|GPS Invalid|DR  Location)\s*:\s*(\S+)\s+N\s+(\S+)\s+E\s+measured\s+(\S+)\s+secs ago)");
  return re;
}

bool parse_fix(const std::smatch& m, SurfaceReport& report) {
  DialogFix fix;
  const std::string label = m[1].str();
  fix.kind = label == "GPS Location"  ? "gps"
             : label == "GPS TooFar"  ? "gps_toofar"
             : label == "GPS Invalid" ? "gps_invalid"
                                      : "dr";
  if (!to_double(m[2].str(), fix.lat_ddmm) || !to_double(m[3].str(), fix.lon_ddmm)) return false;
  fix.lat_deg = ddmm_to_degrees(fix.lat_ddmm);
  fix.lon_deg = ddmm_to_degrees(fix.lon_ddmm);
  fix.age_s = age_of(m[4].str());
  if (fix.kind == "gps") {
    // A valid fix is on the globe; anything else is the console's sentinel (69696969).
    if (std::fabs(fix.lat_deg) > 90.0 || std::fabs(fix.lon_deg) > 180.0) return false;
    report.gps = fix;
  } else if (fix.kind == "dr") {
    report.dr = fix;
  } else {
    report.gps_rejected.push_back(fix);
  }
  return true;
}

bool parse_curr_time(const std::smatch& m, SurfaceReport& report) {
  report.curr_time_text = m[1].str();
  const utc::Parsed parsed = utc::parse_ctime(report.curr_time_text);
  if (parsed.ok) {
    report.curr_time_unix = static_cast<long long>(parsed.whole_s);
  } else {
    report.curr_time_unix.reset();
  }
  double mt = 0.0;
  if (to_double(m[2].str(), mt)) report.mission_time_s = mt;
  return report.curr_time_unix.has_value();
}

void parse_sensor(const std::smatch& m, SurfaceReport& report) {
  DialogSensor sensor{m[1].str(), m[2].str(), m[3].str(), age_of(m[4].str())};
  for (DialogSensor& known : report.sensors) {
    if (known.name == sensor.name) {
      known = sensor;
      return;
    }
  }
  report.sensors.push_back(sensor);
}

bool parse_abort(const std::string& rest, SurfaceReport& report) {
  static const std::regex total(R"(^total since reset:\s*(\d+))");
  static const std::regex last(R"(^last abort (cause|details|time|segment|mission):\s*(.*)$)");
  if (!report.aborts) report.aborts = DialogAborts{};
  std::smatch m;
  if (std::regex_search(rest, m, total)) {
    report.aborts->total_since_reset = std::atoi(m[1].str().c_str());
    return true;
  }
  if (std::regex_search(rest, m, last)) {
    const std::string key = m[1].str();
    std::string value = m[2].str();
    while (!value.empty() && std::isspace(static_cast<unsigned char>(value.back()))) value.pop_back();
    if (key == "cause") report.aborts->last_cause = value;
    if (key == "details") report.aborts->last_details = value;
    if (key == "time") report.aborts->last_time = value;
    if (key == "segment") report.aborts->last_segment = value;
    if (key == "mission") report.aborts->last_mission = value;
    return true;
  }
  return false;
}

}  // namespace

double ddmm_to_degrees(double ddmm) {
  const double magnitude = std::fabs(ddmm);
  const double degrees = std::floor(magnitude / 100.0);
  const double value = degrees + (magnitude - 100.0 * degrees) / 60.0;
  return ddmm < 0.0 ? -value : value;
}

bool valid_glider_name(const std::string& name) {
  static const std::regex re(R"(^[A-Za-z0-9_][A-Za-z0-9_-]{0,31}$)");
  return std::regex_match(name, re);
}

std::string match_prompt(const std::string& text) {
  static const std::regex re(R"((GliderDos|GliderDOS|GliderLAB) [A-Z] -?\d+ >)");
  std::smatch m;
  if (std::regex_search(text, m, re)) return m[0].str();
  return "";
}

bool parse_dialog_line(const std::string& line, SurfaceReport& report) {
  static const std::regex vehicle(R"(^\s*Vehicle Name:\s*(\S+))");
  static const std::regex curr_time(
      R"(^\s*Curr Time:\s*(\w{3}\s+\w{3}\s+\d{1,2}\s+\d{2}:\d{2}:\d{2}\s+\d{4})\s+MT:\s*(\S+))");
  static const std::regex because(R"(^\s*Because:\s*(.*\S))");
  static const std::regex mission(R"(^\s*MissionName:\s*(\S+)\s+MissionNum:\s*(\S+))");
  static const std::regex sensor(R"(^\s*sensor:\s*(\w+)\(([^)]*)\)=(\S+)\s+(\S+)\s+secs ago)");
  static const std::regex devices(
      R"(^\s*devices:\(t/m/s\)\s*errs:\s*(\d+)/\s*(\d+)/\s*(\d+)\s+warn:\s*(\d+)/\s*(\d+)/\s*(\d+)\s+odd:\s*(\d+)/\s*(\d+)/\s*(\d+))");
  static const std::string abort_head = "ABORT HISTORY:";
  ++report.lines;
  const std::string prompt = match_prompt(line);
  if (!prompt.empty()) report.prompt = prompt;
  std::smatch m;
  if (std::regex_search(line, m, vehicle)) {
    if (!valid_glider_name(m[1].str())) {
      ++report.unparsed_lines;
      return false;
    }
    report.vehicle_name = m[1].str();
    return true;
  }
  bool ok = true;
  if (std::regex_search(line, m, curr_time)) {
    ok = parse_curr_time(m, report);
  } else if (std::regex_search(line, m, fix_regex())) {
    ok = parse_fix(m, report);
  } else if (std::regex_search(line, m, sensor)) {
    parse_sensor(m, report);
  } else if (std::regex_search(line, m, because)) {
    // The dialog is re-printed every printout_cycle_time: a reason counts once.
    bool known = false;
    for (const std::string& reason : report.reasons) known = known || reason == m[1].str();
    if (!known) report.reasons.push_back(m[1].str());
  } else if (std::regex_search(line, m, mission)) {
    report.mission_name = m[1].str();
    report.mission_number = m[2].str();
  } else if (std::regex_search(line, m, devices)) {
    DialogDevices d;
    for (int i = 0; i < 3; ++i) {
      d.errors[i] = std::atoi(m[1 + i].str().c_str());
      d.warnings[i] = std::atoi(m[4 + i].str().c_str());
      d.oddities[i] = std::atoi(m[7 + i].str().c_str());
    }
    report.devices = d;
  } else if (const auto at = line.find(abort_head); at != std::string::npos) {
    std::string rest = line.substr(at + abort_head.size());
    rest.erase(0, rest.find_first_not_of(' ') == std::string::npos ? rest.size() : rest.find_first_not_of(' '));
    ok = parse_abort(rest, report);
  } else {
    return !prompt.empty();
  }
  if (!ok) ++report.unparsed_lines;
  return ok;
}

}  // namespace glider::shore
