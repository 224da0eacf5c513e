// SPDX-License-Identifier: Apache-2.0
#include "alert_book.hpp"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <set>

#include "../glider_folders.hpp"
#include "utc_time.hpp"

extern char** environ;

namespace glider::shore::web {
using nlohmann::json;
namespace {

constexpr double kChildLimitS = 30.0;  // a notify command running longer is killed
constexpr std::size_t kKeptRecords = 200;

json number_or_null(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json to_json(const AlertRecord& r) {
  return {{"id", r.id},
          {"glider", r.glider},
          {"kind", r.kind},
          {"message", r.message},
          {"check", r.check},
          {"first_utc", format_utc(r.first_unix)},
          {"first_unix", number_or_null(r.first_unix)},
          {"last_notified_utc", format_utc(r.last_notified_unix)},
          {"last_notified_unix", number_or_null(r.last_notified_unix)},
          {"cleared_utc", format_utc(r.cleared_unix)},
          {"cleared_unix", number_or_null(r.cleared_unix)},
          {"acked_utc", format_utc(r.acked_unix)},
          {"acked_unix", number_or_null(r.acked_unix)},
          {"acked_by", r.acked_by},
          {"notifications", r.notifications},
          {"escalated", r.escalated},
          {"active", r.active}};
}

double number_of(const json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : kUnknown;
}

struct Wanted {
  std::string id, kind, message, check;
};

std::vector<Wanted> conditions(const GliderFacts& g, const ConsoleConfig& c, double now) {
  std::vector<Wanted> wanted;
  if (g.aborted) {
    wanted.push_back({"abort@" + g.last_event_id, "abort",
                      g.name + " aborted its mission" + (g.abort_text.size() > 1 ? ": " + g.abort_text : std::string()),
                      "read the last dialog; the glider is at the surface waiting"});
  }
  if (!g.in_call && std::isfinite(g.expected_latest) && now > g.expected_latest + c.missed_call_margin_s) {
    wanted.push_back({"missed_call@" + g.last_event_id, "missed_call",
                      g.name + " missed its call: expected by " + format_utc(g.expected_latest) + " (" +
                          g.expected_source + "), last call " + format_utc(g.last_call_start),
                      "check the modem link and the forecast's abort risk"});
  }
  if (std::isfinite(g.surface_since)) {
    const double until = g.in_call ? now : g.surface_until;
    const bool still_up = g.in_call || now - g.surface_until < c.surface_gap_s;
    if (std::isfinite(until) && still_up && until - g.surface_since > c.surface_limit_s) {
      wanted.push_back({"surface@" + format_utc(g.surface_since), "surface_too_long",
                        g.name + " at the surface since " + format_utc(g.surface_since) + " (" +
                            std::to_string(static_cast<long>((until - g.surface_since) / 60.0)) + " min)",
                        "is it drifting into danger? resume or recover"});
    }
  }
  for (const HealthAlert& h : g.health_alerts) {
    wanted.push_back({"health:" + h.id, "health", g.name + ": " + h.message, h.check});
  }
  return wanted;
}

}  // namespace

AlertBook::~AlertBook() {
  for (const Child& child : children_) ::waitpid(child.pid, nullptr, WNOHANG);
}

void AlertBook::load(const std::string& glider) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (records_.count(glider) != 0) return;
  std::vector<AlertRecord>& list = records_[glider];
  const json saved = read_json(config_.root / glider / "alerts.json");
  if (!saved.is_object()) return;
  for (const json& j : saved.value("alerts", json::array())) {
    if (!j.is_object()) continue;
    AlertRecord r;
    r.id = j.value("id", "");
    r.glider = glider;
    r.kind = j.value("kind", "");
    r.message = j.value("message", "");
    r.check = j.value("check", "");
    r.first_unix = number_of(j, "first_unix");
    r.last_notified_unix = number_of(j, "last_notified_unix");
    r.cleared_unix = number_of(j, "cleared_unix");
    r.acked_unix = number_of(j, "acked_unix");
    r.acked_by = j.value("acked_by", "");
    r.notifications = j.value("notifications", 0);
    r.escalated = j.value("escalated", false);
    r.active = j.value("active", false);
    if (!r.id.empty()) list.push_back(r);
  }
}

void AlertBook::save(const std::string& glider) const {
  json list = json::array();
  for (const AlertRecord& r : records_.at(glider)) list.push_back(to_json(r));
  const json out = {{"schema", "glider-console-alerts/1"}, {"glider", glider}, {"alerts", list}};
  write_file_atomically(config_.root / glider / "alerts.json", out.dump(2) + "\n");
}

void AlertBook::notify(AlertRecord& r, bool escalate, double now) {
  r.last_notified_unix = now;
  ++r.notifications;
  const std::string& command =
      escalate && !config_.escalate_command.empty() ? config_.escalate_command : config_.notify_command;
  std::fprintf(stderr, "glider-shore console: alert %s %s: %s\n", escalate ? "ESCALATED" : "notified", r.id.c_str(),
               r.message.c_str());
  if (command.empty()) return;
  std::vector<std::string> env_text;
  for (char** e = environ; *e != nullptr; ++e) {
    if (std::string(*e).rfind("GLIDER_ALERT_", 0) != 0) env_text.emplace_back(*e);
  }
  env_text.push_back("GLIDER_ALERT_ID=" + r.id);
  env_text.push_back("GLIDER_ALERT_GLIDER=" + r.glider);
  env_text.push_back("GLIDER_ALERT_KIND=" + r.kind);
  env_text.push_back("GLIDER_ALERT_LEVEL=" + std::string(escalate ? "escalate" : "notify"));
  env_text.push_back("GLIDER_ALERT_COUNT=" + std::to_string(r.notifications));
  env_text.push_back("GLIDER_ALERT_MESSAGE=" + r.message);
  env_text.push_back("GLIDER_ALERT_CHECK=" + r.check);
  std::vector<char*> env;
  for (std::string& text : env_text) env.push_back(text.data());
  env.push_back(nullptr);
  std::string shell = "/bin/sh", dash_c = "-c", script = command;
  char* argv[] = {shell.data(), dash_c.data(), script.data(), nullptr};
  pid_t pid = 0;
  if (::posix_spawn(&pid, "/bin/sh", nullptr, nullptr, argv, env.data()) == 0) {
    children_.push_back({pid, now});
  } else {
    std::fprintf(stderr, "glider-shore console: cannot run the notify command for %s\n", r.id.c_str());
  }
}

void AlertBook::reap(double now) {
  for (auto it = children_.begin(); it != children_.end();) {
    int status = 0;
    const pid_t done = ::waitpid(it->pid, &status, WNOHANG);
    if (done == it->pid || done < 0) {
      if (done == it->pid && !(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
        std::fprintf(stderr, "glider-shore console: the notify command failed (status %d)\n", status);
      }
      it = children_.erase(it);
      continue;
    }
    if (now - it->started > kChildLimitS) ::kill(it->pid, SIGKILL);  // reaped next time
    ++it;
  }
}

bool AlertBook::update(const std::vector<GliderFacts>& gliders, double now) {
  std::lock_guard<std::mutex> lock(mutex_);
  reap(now);
  bool any = false;
  for (const GliderFacts& g : gliders) {
    std::vector<AlertRecord>& list = records_[g.name];
    bool changed = false;
    std::set<std::string> wanted_ids;
    for (const Wanted& w : conditions(g, config_, now)) {
      wanted_ids.insert(w.id);
      auto it = std::find_if(list.begin(), list.end(), [&](const AlertRecord& r) { return r.id == w.id; });
      if (it == list.end()) {
        AlertRecord r;
        r.id = w.id;
        r.glider = g.name;
        r.kind = w.kind;
        r.message = w.message;
        r.check = w.check;
        r.first_unix = now;
        list.push_back(r);
        notify(list.back(), false, now);
        changed = true;
      } else if (!it->active) {
        it->active = true;  // back (e.g. health raised it again)
        it->cleared_unix = kUnknown;
        changed = true;
      }
    }
    for (AlertRecord& r : list) {
      if (r.active && wanted_ids.count(r.id) == 0) {
        r.active = false;
        r.cleared_unix = now;
        changed = true;
      }
      if (!r.active || std::isfinite(r.acked_unix)) continue;
      if (!r.escalated && now - r.first_unix >= config_.escalate_after_s) {
        r.escalated = true;
        notify(r, true, now);
        changed = true;
      } else if (now - r.last_notified_unix >= config_.repeat_s) {
        notify(r, r.escalated, now);
        changed = true;
      }
    }
    if (list.size() > kKeptRecords) {  // forget the oldest quiet ones
      list.erase(std::remove_if(list.begin(), list.begin() + static_cast<long>(list.size() - kKeptRecords),
                                [](const AlertRecord& r) { return !r.active; }),
                 list.begin() + static_cast<long>(list.size() - kKeptRecords));
    }
    if (changed) {
      save(g.name);
      any = true;
    }
  }
  return any;
}

bool AlertBook::acknowledge(const std::string& id, const std::string& user, double now) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto& [glider, list] : records_) {
    for (AlertRecord& r : list) {
      if (r.id != id || std::isfinite(r.acked_unix)) continue;
      r.acked_unix = now;
      r.acked_by = user;
      save(glider);
      return true;
    }
  }
  return false;
}

json AlertBook::for_glider(const std::string& glider) const {
  std::lock_guard<std::mutex> lock(mutex_);
  json out = json::array();
  const auto it = records_.find(glider);
  if (it == records_.end()) return out;
  for (auto r = it->second.rbegin(); r != it->second.rend(); ++r) out.push_back(to_json(*r));
  return out;
}

int AlertBook::open_count(const std::string& glider) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = records_.find(glider);
  int n = 0;
  if (it != records_.end()) {
    for (const AlertRecord& r : it->second) n += r.active && !std::isfinite(r.acked_unix) ? 1 : 0;
  }
  return n;
}

bool AlertBook::has_active(const std::string& glider, const std::string& kind) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = records_.find(glider);
  if (it == records_.end()) return false;
  return std::any_of(it->second.begin(), it->second.end(),
                     [&](const AlertRecord& r) { return r.active && r.kind == kind; });
}

}  // namespace glider::shore::web
