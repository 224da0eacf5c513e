// SPDX-License-Identifier: Apache-2.0
#pragma once
// One glider's shore folder read for the console: the facts the alerts and the
// fleet's ordering use, and the glider page's JSON. Only reads; every file it
// reads appears by rename(2) of a whole file (docs/comms.md, CONTRACTS.md).
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slocum_track.hpp"
#include "utc_time.hpp"

namespace glider::shore::web {

struct HealthAlert {
  std::string id, message, check;
};

struct GliderFacts {
  std::string name;
  std::string last_event_id;
  double last_call_start = kUnknown, last_call_end = kUnknown;
  bool in_call = false;               // the newest journal has no event yet (a call in progress)
  double surface_since = kUnknown;    // start of the current or last stay at the surface
  double surface_until = kUnknown;    // its end (NaN while a call is in progress)
  double expected_call = kUnknown;    // next call, from the forecast or else from the call interval
  double expected_latest = kUnknown;  // the forecast's p90 (or the expected call)
  std::string expected_source;        // "forecast" | "call interval" | ""
  bool aborted = false;               // the last call's prompt says the mission aborted
  std::string abort_text;             // cause as the dialog said it
  std::string health_state;           // "" = no health report yet
  std::vector<HealthAlert> health_alerts;
  double abort_risk = kUnknown;  // forecast's
};

class GliderReader {
 public:
  GliderReader(std::filesystem::path root, std::string name, double surface_gap_s)
      : root_(std::move(root)), name_(std::move(name)), surface_gap_s_(surface_gap_s) {}
  // Reads the folder again (events and CSVs are cached: they never change once written).
  void read(double now);
  const GliderFacts& facts() const { return facts_; }
  const nlohmann::json& detail() const { return detail_; }    // the glider page (without alerts)
  const nlohmann::json& summary() const { return summary_; }  // its fleet row (without alerts)

 private:
  struct JournalEntry {
    std::uintmax_t size = 0;
    std::filesystem::file_time_type mtime;
    std::vector<std::string> excerpt;
  };
  const std::vector<std::string>& excerpt(const std::filesystem::path& journal);

  std::filesystem::path root_;
  std::string name_;
  double surface_gap_s_;
  std::map<std::string, nlohmann::json> events_;  // by call ID
  std::map<std::string, JournalEntry> journals_;
  TrackCache tracks_;
  GliderFacts facts_;
  nlohmann::json detail_, summary_;
};

// A file's content, or "" (missing or unreadable); at most `limit` bytes from its end.
std::string read_tail(const std::filesystem::path& file, std::size_t limit);
// A JSON file, or null when missing or not JSON.
nlohmann::json read_json(const std::filesystem::path& file);

}  // namespace glider::shore::web
