// SPDX-License-Identifier: Apache-2.0
#include "surfacing_event.hpp"

#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "glider_folders.hpp"

namespace glider::shore {
namespace {

using nlohmann::json;

json optional_number(const std::optional<double>& value) { return value ? json(*value) : json(nullptr); }

json fix_json(const std::optional<DialogFix>& fix) {
  if (!fix) return nullptr;
  return json{{"kind", fix->kind},       {"lat_ddmm", fix->lat_ddmm}, {"lon_ddmm", fix->lon_ddmm},
              {"lat_deg", fix->lat_deg}, {"lon_deg", fix->lon_deg},   {"age_s", optional_number(fix->age_s)}};
}

// A sensor value as a number when it is one, else the printed text.
json sensor_value(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() && *end == '\0' && std::isfinite(value)) return value;
  return text;
}

json report_json(const SurfaceReport& r) {
  json out;
  out["vehicle_name"] = r.vehicle_name.empty() ? json(nullptr) : json(r.vehicle_name);
  out["glider_time"] =
      r.curr_time_text.empty()
          ? json(nullptr)
          : json{{"text", r.curr_time_text},
                 {"utc", r.curr_time_unix ? json(utc_iso(static_cast<double>(*r.curr_time_unix))) : json(nullptr)},
                 {"mission_time_s", optional_number(r.mission_time_s)}};
  out["reasons"] = r.reasons;
  out["mission"] =
      r.mission_name.empty() ? json(nullptr) : json{{"name", r.mission_name}, {"number", r.mission_number}};
  out["gps"] = fix_json(r.gps);
  json rejected = json::array();
  for (const DialogFix& fix : r.gps_rejected) rejected.push_back(fix_json(fix));
  out["gps_rejected"] = rejected;
  out["dr"] = fix_json(r.dr);
  json sensors = json::array();
  for (const DialogSensor& s : r.sensors) {
    sensors.push_back(
        {{"name", s.name}, {"unit", s.unit}, {"value", sensor_value(s.value)}, {"age_s", optional_number(s.age_s)}});
  }
  out["sensors"] = sensors;
  if (r.aborts) {
    out["aborts"] = {
        {"total_since_reset", r.aborts->total_since_reset < 0 ? json(nullptr) : json(r.aborts->total_since_reset)},
        {"last_cause", r.aborts->last_cause},
        {"last_details", r.aborts->last_details},
        {"last_time", r.aborts->last_time},
        {"last_segment", r.aborts->last_segment},
        {"last_mission", r.aborts->last_mission}};
  } else {
    out["aborts"] = nullptr;
  }
  if (r.devices) {
    const DialogDevices& d = *r.devices;
    out["devices"] = {{"errors", {d.errors[0], d.errors[1], d.errors[2]}},
                      {"warnings", {d.warnings[0], d.warnings[1], d.warnings[2]}},
                      {"oddities", {d.oddities[0], d.oddities[1], d.oddities[2]}}};
  } else {
    out["devices"] = nullptr;
  }
  out["prompt"] = r.prompt.empty() ? json(nullptr) : json(r.prompt);
  out["dialog_lines"] = r.lines;
  out["unparsed_lines"] = r.unparsed_lines;
  return out;
}

}  // namespace

std::string surface_report_json(const SurfaceReport& report) { return report_json(report).dump(2) + "\n"; }

std::string surfacing_event_json(const CallRecord& call) {
  json out;
  out["schema"] = "glider-shore-surfacing/1";
  out["glider"] = call.glider;
  out["peer"] = call.peer;
  out["call_start_utc"] = utc_iso(call.start_unix);
  out["call_end_utc"] = utc_iso(call.end_unix);
  out["call_duration_s"] = call.end_unix - call.start_unix;
  out["end_reason"] = call.end_reason;
  out["journal"] = call.journal;
  const json report = report_json(call.report);
  for (auto it = report.begin(); it != report.end(); ++it) out[it.key()] = it.value();
  out["commands_sent"] = call.commands_sent;
  json sent = json::array();
  for (const SentFile& f : call.files_sent) {
    sent.push_back({{"name", f.name}, {"bytes", f.bytes}, {"delivered", f.delivered}});
  }
  out["files_sent"] = sent;
  json received = json::array();
  for (const ReceivedFile& f : call.files_received) {
    received.push_back({{"name", f.name},
                        {"bytes", f.bytes},
                        {"status", f.status},
                        {"csv", f.csv.empty() ? json(nullptr) : json(f.csv)},
                        {"csv_error", f.csv_error.empty() ? json(nullptr) : json(f.csv_error)}});
  }
  out["files_received"] = received;
  out["partial_files"] = call.partial_files;
  out["notes"] = call.notes;
  return out.dump(2) + "\n";
}

}  // namespace glider::shore
