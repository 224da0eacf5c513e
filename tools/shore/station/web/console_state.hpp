// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the pages show, kept current by one thread: every tick it looks at the
// folders' modification times (cheap stat calls), re-reads a glider only when
// its folders changed, updates the alerts and publishes an immutable snapshot
// of ready JSON text. Requests only copy a shared pointer, so a page costs the
// same with 1 or 200 clients; event streams wait for the next version.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "alert_book.hpp"
#include "console_config.hpp"
#include "glider_reader.hpp"

namespace glider::shore::web {

struct Snapshot {
  std::uint64_t version = 0;
  std::string fleet;                           // /api/fleet
  std::map<std::string, std::string> gliders;  // /api/gliders/NAME
};

class ConsoleState {
 public:
  explicit ConsoleState(const ConsoleConfig& config) : config_(config), alerts_(config) {}
  ~ConsoleState() { stop(); }
  ConsoleState(const ConsoleState&) = delete;
  ConsoleState& operator=(const ConsoleState&) = delete;

  void start();  // the first snapshot is built before it returns
  void stop();
  void poke();  // something changed (an action): look now and publish, not at the next tick
  std::shared_ptr<const Snapshot> snapshot() const;
  // Waits until the version differs from `seen` or `timeout_s` passes or stop; returns the current snapshot.
  std::shared_ptr<const Snapshot> wait_change(std::uint64_t seen, double timeout_s) const;
  AlertBook& alerts() { return alerts_; }
  bool stopping() const { return stop_; }

 private:
  void run();
  void tick(bool force);  // force: publish a new snapshot even if no folder changed
  std::string signature(const std::string& glider) const;

  const ConsoleConfig& config_;
  AlertBook alerts_;
  std::map<std::string, std::unique_ptr<GliderReader>> readers_;
  std::map<std::string, std::string> signatures_;
  std::shared_ptr<const Snapshot> snapshot_ = std::make_shared<Snapshot>();
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::condition_variable wake_;
  bool poked_ = false;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace glider::shore::web
