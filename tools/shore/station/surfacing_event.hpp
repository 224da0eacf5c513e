// SPDX-License-Identifier: Apache-2.0
#pragma once
// One JSON document per call (surfacing): schema "glider-shore-surfacing/1",
// documented in docs/comms.md ("Surfacing event").
#include <string>
#include <vector>

#include "surface_dialog.hpp"

namespace glider::shore {

struct ReceivedFile {
  std::string name;
  unsigned long long bytes = 0;
  std::string status;  // "new", "replaced" or "duplicate" (same bytes as the published file: dropped)
  std::string csv;     // NAME.csv written beside it, or ""
  std::string csv_error;
};

struct SentFile {
  std::string name;
  unsigned long long bytes = 0;
  bool delivered = false;
};

struct CallRecord {
  std::string glider;
  std::string peer;
  double start_unix = 0.0, end_unix = 0.0;
  std::string end_reason;  // "hangup", "linger ended", "call timeout", "carrier lost during transfer", ...
  std::string journal;     // the journal file name in logs/
  SurfaceReport report;
  std::vector<std::string> commands_sent;
  std::vector<SentFile> files_sent;
  std::vector<ReceivedFile> files_received;
  std::vector<std::string> partial_files;  // kept in .incoming/ for resume, not published
  std::vector<std::string> notes;          // transfer failures and other trouble
};

std::string surfacing_event_json(const CallRecord& call);
// The report alone (`glider-shore dialog FILE`).
std::string surface_report_json(const SurfaceReport& report);

}  // namespace glider::shore
