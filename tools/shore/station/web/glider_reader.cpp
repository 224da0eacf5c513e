// SPDX-License-Identifier: Apache-2.0
#include "glider_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "mission_waypoints.hpp"
#include "utc_time.hpp"

namespace glider::shore::web {
namespace fs = std::filesystem;
using nlohmann::json;
namespace {

constexpr double kStaleCallS = 7200.0;  // a journal without an event older than this is a dead call, not a call
constexpr std::size_t kTranscriptBytes = 64 * 1024;
constexpr std::size_t kMaxTrackPoints = 3000;
constexpr std::size_t kExcerptLines = 8;
constexpr double kUnixClockFrom_s = 1e8;  // a time above this (1973) is a clock's, below it seconds since a start

bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

// Regular files of a folder (hidden ones skipped), sorted by name.
std::vector<fs::path> files_in(const fs::path& folder) {
  std::vector<fs::path> files;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (!name.empty() && name[0] != '.' && it->is_regular_file(error)) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

json number_or_null(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json string_or_null(const std::string& text) { return text.empty() ? json(nullptr) : json(text); }

double json_number(const json& object, const char* key) {
  if (!object.is_object()) return kUnknown;
  const auto it = object.find(key);
  return it != object.end() && it->is_number() ? it->get<double>() : kUnknown;
}

std::string json_text(const json& object, const char* key) {
  if (!object.is_object()) return "";
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : "";
}

json file_list(const std::vector<fs::path>& files) {
  json out = json::array();
  std::error_code error;
  for (const fs::path& file : files) {
    const auto size = fs::file_size(file, error);
    out.push_back({{"name", file.filename().string()}, {"bytes", error ? 0 : size}});
  }
  return out;
}

bool prompt_says_abort(const std::string& prompt) {
  // "GliderDos A 17 >": the letter after the shell's name is how the last mission ended.
  const std::size_t space = prompt.find(' ');
  return space != std::string::npos && prompt.compare(space, 3, " A ") == 0;
}

}  // namespace

std::string read_tail(const fs::path& file, std::size_t limit) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) return "";
  const std::streamoff size = in.tellg();
  const std::streamoff start =
      size > static_cast<std::streamoff>(limit) ? size - static_cast<std::streamoff>(limit) : 0;
  in.seekg(start);
  std::string text(static_cast<std::size_t>(size - start), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return nullptr;
  json value = json::parse(in, nullptr, false);
  return value.is_discarded() ? json(nullptr) : value;
}

const std::vector<std::string>& GliderReader::excerpt(const fs::path& journal) {
  std::error_code error;
  const auto size = fs::file_size(journal, error);
  const auto mtime = fs::last_write_time(journal, error);
  JournalEntry& entry = journals_[journal.filename().string()];
  if (entry.size == size && entry.mtime == mtime) return entry.excerpt;
  entry = JournalEntry{size, mtime, {}};
  std::ifstream in(journal);
  static const char* const kKeys[] = {"Because:", "ABORT HISTORY", "last abort cause", "accepted", "refused", "ERROR"};
  for (std::string line; std::getline(in, line) && entry.excerpt.size() < kExcerptLines;) {
    const std::size_t mark = line.find(" < ");
    if (mark == std::string::npos) continue;
    const std::string text = line.substr(mark + 3);
    for (const char* key : kKeys) {
      if (text.find(key) != std::string::npos) {
        entry.excerpt.push_back(text.substr(0, 200));
        break;
      }
    }
  }
  return entry.excerpt;
}

void GliderReader::read(double now) {
  const fs::path base = root_ / name_;
  GliderFacts facts;
  facts.name = name_;

  // Events (immutable once written) and journals.
  std::string newest_journal;
  fs::path newest_journal_path;
  for (const fs::path& file : files_in(base / "logs")) {
    const std::string name = file.filename().string();
    if (ends_with(name, ".surfacing.json")) {
      const std::string id = name.substr(0, name.size() - 15);
      if (events_.count(id) == 0) {
        json event = read_json(file);
        if (event.is_object()) events_[id] = std::move(event);
      }
    } else if (ends_with(name, ".journal") && name > newest_journal) {
      newest_journal = name;
      newest_journal_path = file;
    }
  }

  // Track and DR errors from the received files' conversions.
  const std::vector<TrackPoint> points = tracks_.read(base / "from-glider");
  const std::vector<DrError> errors = dr_errors(points);
  json track = json::array();
  std::size_t dr_count = 0;
  for (const TrackPoint& p : points) dr_count += p.gps ? 0 : 1;
  const std::size_t stride = std::max<std::size_t>(1, (dr_count + kMaxTrackPoints - 1) / kMaxTrackPoints);
  std::size_t k = 0;
  for (const TrackPoint& p : points) {
    if (!p.gps && (k++ % stride) == 0) track.push_back({p.lat, p.lon});
  }

  json surfacings = json::array(), fixes = json::array();
  double previous_abort_total = 0.0;
  double stay_start = kUnknown, stay_end = kUnknown;
  for (const auto& [id, event] : events_) {
    const double start = parse_utc(json_text(event, "call_start_utc"));
    const double end = parse_utc(json_text(event, "call_end_utc"));
    if (std::isfinite(start)) {
      if (!std::isfinite(stay_end) || start - stay_end > surface_gap_s_) stay_start = start;
      stay_end = std::isfinite(end) ? end : start;
    }
    const json& gps = event.contains("gps") ? event["gps"] : json(nullptr);
    if (gps.is_object())
      fixes.push_back({gps.value("lat_deg", 0.0), gps.value("lon_deg", 0.0), event.value("call_start_utc", "")});
    const json glider_time = event.value("glider_time", json::object());
    const double mission_time = json_number(glider_time, "mission_time_s");
    const double glider_utc = parse_utc(json_text(glider_time, "utc"));
    double dr_error = kUnknown;
    for (const DrError& e : errors) {  // the fix of this surfacing: within 15 min before the dialog's time
      // On the files' clock: a Slocum's m_present_time is Unix seconds (the dialog's Curr Time); files
      // counting from the mission's start (SIL before it wrote UTC) are matched by the mission time.
      const double t = e.t > kUnixClockFrom_s ? glider_utc : mission_time;
      if (std::isfinite(t) && e.t <= t + 60.0 && e.t >= t - 900.0) dr_error = e.error_m;
    }
    json files = json::array();
    for (const json& f : event.value("files_received", json::array())) files.push_back(f.value("name", ""));
    const json aborts = event.value("aborts", json::object());
    const double abort_total = json_number(aborts, "total_since_reset");
    const std::string journal = json_text(event, "journal");
    surfacings.push_back({{"id", id},
                          {"call_start_utc", event.value("call_start_utc", "")},
                          {"call_end_utc", event.value("call_end_utc", "")},
                          {"duration_s", event.value("call_duration_s", json(nullptr))},
                          {"end_reason", event.value("end_reason", "")},
                          {"reasons", event.value("reasons", json::array())},
                          {"gps", gps},
                          {"mission", event.value("mission", json(nullptr))},
                          {"mission_time_s", number_or_null(mission_time)},
                          {"dr_error_m", number_or_null(dr_error)},
                          {"files_received", files},
                          {"files_sent", event.value("files_sent", json::array())},
                          {"commands_sent", event.value("commands_sent", json::array())},
                          {"prompt", event.value("prompt", json(nullptr))},
                          {"aborts_total", number_or_null(abort_total)},
                          {"excerpt", journal.empty() ? json::array() : json(excerpt(base / "logs" / journal))}});
    facts.last_event_id = id;
    facts.last_call_start = start;
    facts.last_call_end = end;
    const std::string prompt = json_text(event, "prompt");
    facts.aborted = prompt_says_abort(prompt) || (std::isfinite(abort_total) && abort_total > previous_abort_total);
    facts.abort_text = facts.aborted ? json_text(aborts, "last_cause") + " " + json_text(aborts, "last_details") : "";
    if (std::isfinite(abort_total)) previous_abort_total = abort_total;
  }
  facts.surface_since = stay_start;
  facts.surface_until = stay_end;

  // A call in progress: the newest journal has no event yet and is fresh.
  if (!newest_journal.empty()) {
    const std::string id = newest_journal.substr(0, newest_journal.size() - 8);
    const double started = parse_call_id(id);
    if (events_.count(id) == 0 && std::isfinite(started) && now - started < kStaleCallS) {
      facts.in_call = true;
      if (!std::isfinite(stay_end) || started - stay_end > surface_gap_s_) facts.surface_since = started;
      facts.surface_until = kUnknown;
    }
  }

  // Forecast: the next expected call; else the call interval (median of the last five).
  json forecast = read_json(base / "forecast" / "forecast.json");
  if (facts.aborted && forecast.is_object() && forecast.contains("next_surfacing")) {
    // The forecast flies the dive cycle on from the last fix; an aborted glider waits at the surface in
    // GliderDos for the pilot instead: its next surfacing is not the forecast's. Shown as set aside.
    forecast = {{"schema", forecast.value("schema", "")},
                {"made_utc", forecast.value("made_utc", "")},
                {"error",
                 "set aside: the glider aborted at its last call and waits at the surface for the pilot; "
                 "the forecast flies on as if it dived"}};
  }
  if (forecast.is_object() && forecast.contains("next_surfacing")) {
    const json& next = forecast["next_surfacing"];
    facts.expected_call = parse_utc(json_text(next, "time_utc"));
    facts.expected_latest = parse_utc(json_text(next, "time_p90_utc"));
    if (!std::isfinite(facts.expected_latest)) facts.expected_latest = facts.expected_call;
    facts.expected_source = std::isfinite(facts.expected_call) ? "forecast" : "";
    facts.abort_risk = json_number(forecast, "abort_risk");
  }
  if (facts.expected_source.empty() && events_.size() >= 3) {
    std::vector<double> starts, gaps;
    for (const auto& [id, event] : events_) starts.push_back(parse_utc(json_text(event, "call_start_utc")));
    for (std::size_t i = starts.size() > 6 ? starts.size() - 6 : 1; i < starts.size(); ++i) {
      if (std::isfinite(starts[i]) && std::isfinite(starts[i - 1])) gaps.push_back(starts[i] - starts[i - 1]);
    }
    if (!gaps.empty()) {
      std::sort(gaps.begin(), gaps.end());
      facts.expected_call = facts.last_call_start + gaps[gaps.size() / 2];
      facts.expected_latest = facts.expected_call;
      facts.expected_source = "call interval";
    }
  }

  // Health.
  const json health = read_json(base / "health" / "health.json");
  if (health.is_object()) {
    facts.health_state = json_text(health, "state");
    for (const json& alert : health.value("alerts", json::array())) {
      facts.health_alerts.push_back({json_text(alert, "id"), json_text(alert, "message"), json_text(alert, "check")});
    }
  }
  json plots = json::array();
  for (const fs::path& file : files_in(base / "health" / "plots")) {
    if (file.extension() == ".png") plots.push_back(file.filename().string());
  }

  // Waypoints: the pilot's copy of the mission, replaced by a later sent file of the same name.
  std::map<std::string, json> waypoint_files;
  auto add_waypoints = [&](const fs::path& file, const std::string& name, const std::string& source) {
    const auto found = read_waypoints(file);
    if (found.empty()) return;
    json list = json::array();
    for (const auto& [lat, lon] : found) list.push_back({lat, lon});
    waypoint_files[name] = {{"file", name}, {"source", source}, {"points", list}};
  };
  // mission/mafiles/ is the forecast's layout (mission/missions/*.mi beside it); plain mission/*.ma is taken too.
  for (const char* folder : {"mission", "mission/mafiles"}) {
    for (const fs::path& file : files_in(base / folder)) {
      if (file.extension() == ".ma") add_waypoints(file, file.filename().string(), std::string(folder) + "/");
    }
  }
  const std::vector<fs::path> sent = files_in(base / "to-glider" / "sent");
  for (const fs::path& file : sent) {
    const std::string name = file.filename().string();
    if (file.extension() == ".ma" && name.size() > 16 && name[15] == '_') {
      add_waypoints(file, name.substr(16), "sent " + name.substr(0, 15));
    }
  }
  json waypoints = json::array();
  for (const auto& [name, entry] : waypoint_files) waypoints.push_back(entry);

  json rehearsals = json::array();
  for (const fs::path& file : files_in(base / "forecast" / "rehearsals")) {
    if (file.extension() == ".json") rehearsals.push_back(read_json(file));
  }
  json commands = json::array();
  {
    std::ifstream in(base / "commands.queue");
    for (std::string line; std::getline(in, line);) {
      if (!line.empty()) commands.push_back(line);
    }
  }
  json actions = json::array();
  {
    std::istringstream lines(read_tail(base / "actions.journal", 64 * 1024));
    std::vector<json> all;
    for (std::string line; std::getline(lines, line);) {
      json action = json::parse(line, nullptr, false);
      if (action.is_object()) all.push_back(action);
    }
    for (std::size_t i = all.size() > 50 ? all.size() - 50 : 0; i < all.size(); ++i) actions.push_back(all[i]);
  }

  json last_surfacing = surfacings.empty() ? json(nullptr) : surfacings.back();
  json next_call = nullptr;
  if (!facts.expected_source.empty()) {
    next_call = {{"utc", format_utc(facts.expected_call)},
                 {"latest_utc", format_utc(facts.expected_latest)},
                 {"source", facts.expected_source}};
  }
  json abort = {{"aborted", facts.aborted},
                {"cause", string_or_null(facts.abort_text)},
                {"total_since_reset", last_surfacing.is_object() ? last_surfacing["aborts_total"] : json(nullptr)}};
  summary_ = {{"name", name_},
              {"last_call_start_utc", string_or_null(format_utc(facts.last_call_start))},
              {"last_call_end_utc", string_or_null(format_utc(facts.last_call_end))},
              {"in_call", facts.in_call},
              {"surface_since_utc", string_or_null(format_utc(facts.surface_since))},
              {"fix", last_surfacing.is_object() ? last_surfacing["gps"] : json(nullptr)},
              {"reasons", last_surfacing.is_object() ? last_surfacing["reasons"] : json::array()},
              {"mission", last_surfacing.is_object() ? last_surfacing["mission"] : json(nullptr)},
              {"next_call", next_call},
              {"health_state", string_or_null(facts.health_state)},
              {"abort", abort},
              {"abort_risk", number_or_null(facts.abort_risk)},
              {"surfacings", surfacings.size()},
              {"queued", commands.size() + files_in(base / "to-glider").size()}};
  detail_ = summary_;
  detail_["surfacings"] = surfacings;
  detail_["fixes"] = fixes;
  detail_["dr_track"] = track;
  json dr_list = json::array();
  for (const DrError& e : errors) dr_list.push_back({{"m_present_time", e.t}, {"error_m", e.error_m}});
  detail_["dr_errors"] = dr_list;
  detail_["waypoints"] = waypoints;
  detail_["forecast"] = forecast;
  detail_["health"] = health;
  detail_["plots"] = plots;
  detail_["rehearsals"] = rehearsals;
  detail_["transcript"] = {{"journal", string_or_null(newest_journal)},
                           {"text", newest_journal.empty() ? "" : read_tail(newest_journal_path, kTranscriptBytes)}};
  detail_["queued_files"] = file_list(files_in(base / "to-glider"));
  detail_["queued_commands"] = commands;
  detail_["sent_files"] = file_list(sent);
  detail_["actions"] = actions;
  facts_ = std::move(facts);
}

}  // namespace glider::shore::web
