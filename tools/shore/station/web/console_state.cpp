// SPDX-License-Identifier: Apache-2.0
#include "console_state.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "../glider_folders.hpp"
#include "../surface_dialog.hpp"
#include "utc_time.hpp"

namespace glider::shore::web {
namespace fs = std::filesystem;
using nlohmann::json;
namespace {

std::string dump(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

// Why a glider needs attention, most urgent first (rank 0).
json attention(const GliderFacts& f, const AlertBook& alerts, int open) {
  int rank = 6;
  std::string why = "ok";
  if (f.aborted || alerts.has_active(f.name, "abort")) {
    rank = 0;
    why = "aborted";
  } else if (alerts.has_active(f.name, "missed_call")) {
    rank = 1;
    why = "missed its call";
  } else if (alerts.has_active(f.name, "surface_too_long")) {
    rank = 2;
    why = "at the surface too long";
  } else if (f.health_state == "alert" || alerts.has_active(f.name, "health")) {
    rank = 3;
    why = "health alert";
  } else if (std::isfinite(f.abort_risk) && f.abort_risk >= 0.2) {
    rank = 4;
    why = "forecast abort risk " + std::to_string(static_cast<int>(std::lround(100 * f.abort_risk))) + " %";
  } else if (f.health_state.empty() || f.health_state == "cannot judge") {
    rank = 5;
    why = f.health_state.empty() ? "no health report yet" : "health cannot judge";
  }
  return {{"rank", rank}, {"why", why}, {"open_alerts", open}};
}

}  // namespace

void ConsoleState::start() {
  tick(true);
  thread_ = std::thread([this] { run(); });
}

void ConsoleState::stop() {
  if (stop_.exchange(true)) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    poked_ = true;
  }
  wake_.notify_all();
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void ConsoleState::poke() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    poked_ = true;
  }
  wake_.notify_all();
}

std::shared_ptr<const Snapshot> ConsoleState::snapshot() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return snapshot_;
}

std::shared_ptr<const Snapshot> ConsoleState::wait_change(std::uint64_t seen, double timeout_s) const {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait_for(lock, std::chrono::duration<double>(timeout_s),
                    [&] { return stop_ || snapshot_->version != seen; });
  return snapshot_;
}

void ConsoleState::run() {
  while (!stop_) {
    bool force = false;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait_for(lock, std::chrono::duration<double>(config_.tick_s), [this] { return poked_; });
      force = poked_;
      poked_ = false;
    }
    if (stop_) break;
    try {
      tick(force);
    } catch (const std::exception& failure) {  // a folder that vanished mid-read: next tick
      std::fprintf(stderr, "glider-shore console: %s\n", failure.what());
    }
  }
}

// Modification times and sizes of everything the pages show: a rename into a
// folder changes the folder's mtime, a growing journal its size.
std::string ConsoleState::signature(const std::string& glider) const {
  static const char* const kPaths[] = {"logs",
                                       "to-glider",
                                       "to-glider/sent",
                                       "from-glider",
                                       "health",
                                       "health/plots",
                                       "health/health.json",
                                       "forecast",
                                       "forecast/forecast.json",
                                       "forecast/rehearsals",
                                       "commands.queue",
                                       "actions.journal",
                                       "mission"};
  std::string text;
  const fs::path base = config_.root / glider;
  for (const char* path : kPaths) {
    struct stat st {};
    if (::stat((base / path).c_str(), &st) == 0) {
      text += std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec) + ":" +
              std::to_string(st.st_size) + ";";
    } else {
      text += "-;";
    }
  }
  return text;
}

void ConsoleState::tick(bool force) {
  const double now = now_unix();
  std::vector<std::string> names;
  std::error_code error;
  for (fs::directory_iterator it(config_.root, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name != "unidentified" && valid_glider_name(name) && it->is_directory(error)) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  bool changed = force;
  // The newest journal grows during a call: its size is in the logs folder's signature only through the folder,
  // so a call in progress is re-read every tick (cheap: events and CSVs are cached).
  for (const std::string& name : names) {
    std::string sig = signature(name);
    auto& reader = readers_[name];
    const bool fresh = reader == nullptr;
    if (fresh) {
      reader = std::make_unique<GliderReader>(config_.root, name, config_.surface_gap_s);
      alerts_.load(name);
    }
    if (fresh || sig != signatures_[name] || reader->facts().in_call) {
      reader->read(now);
      signatures_[name] = std::move(sig);
      changed = true;
    }
  }
  if (names.size() != readers_.size()) {  // a glider folder went away
    for (auto it = readers_.begin(); it != readers_.end();) {
      it = std::binary_search(names.begin(), names.end(), it->first) ? std::next(it) : readers_.erase(it);
    }
    changed = true;
  }
  std::vector<GliderFacts> facts;
  for (const auto& [name, reader] : readers_) facts.push_back(reader->facts());
  changed = alerts_.update(facts, now) || changed;
  if (!changed && snapshot()->version != 0) return;

  auto next = std::make_shared<Snapshot>();
  json rows = json::array();
  for (const auto& [name, reader] : readers_) {
    const json alerts = alerts_.for_glider(name);
    const int open = alerts_.open_count(name);
    json row = reader->summary();
    row["alerts"] = alerts;
    row["attention"] = attention(reader->facts(), alerts_, open);
    rows.push_back(row);
    json detail = reader->detail();
    detail["alerts"] = alerts;
    detail["attention"] = row["attention"];
    next->gliders[name] = dump(detail);
  }
  std::stable_sort(rows.begin(), rows.end(), [](const json& a, const json& b) {
    const int ra = a["attention"]["rank"], rb = b["attention"]["rank"];
    if (ra != rb) return ra < rb;
    const int oa = a["attention"]["open_alerts"], ob = b["attention"]["open_alerts"];
    if (oa != ob) return oa > ob;
    return a["name"].get<std::string>() < b["name"].get<std::string>();
  });
  {
    std::lock_guard<std::mutex> lock(mutex_);
    next->version = snapshot_->version + 1;
    next->fleet = dump({{"version", next->version}, {"made_utc", format_utc(now)}, {"gliders", rows}});
    snapshot_ = next;
  }
  changed_.notify_all();
}

}  // namespace glider::shore::web
