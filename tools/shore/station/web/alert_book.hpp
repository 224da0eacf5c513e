// SPDX-License-Identifier: Apache-2.0
#pragma once
// Alerts to people (docs/console.md, "Alerts"): from each glider's facts the
// conditions a pilot must hear about - an abort, a call missed by a margin,
// too long at the surface, a health alert - each one a record that is
// notified through a pluggable command, repeated and escalated while nobody
// acknowledges it on the page, and quiet once acknowledged or cleared.
// State per glider in ROOT/GLIDER/alerts.json (survives a restart).
#include <sys/types.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "console_config.hpp"
#include "glider_reader.hpp"
#include "utc_time.hpp"

namespace glider::shore::web {

struct AlertRecord {
  std::string id, glider, kind, message, check;
  double first_unix = kUnknown, last_notified_unix = kUnknown, cleared_unix = kUnknown, acked_unix = kUnknown;
  int notifications = 0;
  bool escalated = false, active = true;
  std::string acked_by;
};

class AlertBook {
 public:
  explicit AlertBook(const ConsoleConfig& config) : config_(config) {}
  ~AlertBook();
  AlertBook(const AlertBook&) = delete;
  AlertBook& operator=(const AlertBook&) = delete;

  void load(const std::string& glider);  // reads ROOT/GLIDER/alerts.json once
  // Raises, clears, notifies, repeats, escalates; returns true when any record changed.
  bool update(const std::vector<GliderFacts>& gliders, double now);
  // false: no such alert. An acknowledged alert is never notified again.
  bool acknowledge(const std::string& id, const std::string& user, double now);
  nlohmann::json for_glider(const std::string& glider) const;  // newest first
  int open_count(const std::string& glider) const;             // active and not acknowledged
  bool has_active(const std::string& glider, const std::string& kind) const;

 private:
  void notify(AlertRecord& record, bool escalate, double now);
  void reap(double now);
  void save(const std::string& glider) const;

  const ConsoleConfig& config_;
  mutable std::mutex mutex_;
  std::map<std::string, std::vector<AlertRecord>> records_;  // by glider, oldest first
  struct Child {
    pid_t pid;
    double started;
  };
  std::vector<Child> children_;
};

}  // namespace glider::shore::web
