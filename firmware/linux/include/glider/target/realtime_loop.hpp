// SPDX-License-Identifier: Apache-2.0
#pragma once
// The fixed-step loop on Linux: the Executive's cycles at absolute
// deadlines on CLOCK_MONOTONIC (a timerfd armed with TFD_TIMER_ABSTIME, so
// a late cycle does not shift the ones after it), SIGTERM/SIGINT through a
// signalfd (the loop stops between cycles, never inside one), optional
// SCHED_FIFO and mlockall, wake-up jitter statistics, and the systemd
// watchdog (sd_notify WATCHDOG=1 after each healthy cycle) so that a hung
// loop is restarted.
#include <cstdio>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "glider/firmware/executive.hpp"
#include "glider/target/loop_clock.hpp"
#include "glider/target/loop_timing.hpp"

namespace glider::target {

struct RealtimeOptions {
  bool sched_fifo = false;
  int priority = 50;  // SCHED_FIFO 1..99
  bool lock_memory = false;
  hal::Micros stats_every_us = 60'000'000;  // a jitter line in the log this often
};

// Applies SCHED_FIFO and mlockall as asked. Not permitted (no CAP_SYS_NICE /
// CAP_IPC_LOCK, RLIMIT_MEMLOCK) is a warning, returned; the loop runs anyway.
std::string apply_realtime(const RealtimeOptions& options);

// Blocks SIGTERM and SIGINT in the calling thread and every thread it starts
// afterwards, so that they reach the loop's signalfd only. Call first in
// main(), before any thread exists (the flight log's writer is one).
void block_stop_signals();

enum class StopReason { kSignal, kDone, kError, kCycleLimit };

class RealtimeLoop {
 public:
  // Start-up: blocks SIGTERM and SIGINT for signalfd, creates the timerfd.
  // Throws std::runtime_error when the kernel refuses.
  // `clock` is the executive's: its deadlines are converted to CLOCK_MONOTONIC.
  RealtimeLoop(fw::Executive& executive, const LoopClock& clock, const RealtimeOptions& options, std::FILE* log);
  ~RealtimeLoop();
  RealtimeLoop(const RealtimeLoop&) = delete;
  RealtimeLoop& operator=(const RealtimeLoop&) = delete;

  // Runs cycles until a signal, `done()` true after a cycle, or `max_cycles`
  // (0: no limit). `healthy()` after each cycle decides whether the watchdog
  // is fed. Tells systemd READY=1 before the first cycle, STOPPING=1 after.
  StopReason run(const std::function<bool()>& done, const std::function<bool()>& healthy, std::uint64_t max_cycles = 0);

  const LoopTiming& timing() const { return timing_; }
  // Cycles worth watching on their own (glider-firmware: a Zmodem transfer
  // running, the HIL check's "lateness during a transfer"): each one for
  // which `tagged()`, asked at its wake-up, is true has its wake-up lateness
  // kept, up to kTaggedCapacity cycles (kept at init: no heap in the loop).
  static constexpr std::size_t kTaggedCapacity = 65536;
  void set_tagged(std::function<bool()> tagged) { tagged_ = std::move(tagged); }
  std::span<const hal::Micros> tagged_lateness_us() const { return tagged_lateness_us_; }
  bool watchdog_enabled() const { return watchdog_us_ > 0; }
  std::uint64_t watchdog_pings() const { return watchdog_pings_; }

 private:
  bool wait_until(hal::Micros deadline_us, bool& signalled);

  fw::Executive& executive_;
  const LoopClock& clock_;
  RealtimeOptions options_;
  std::FILE* log_;
  int timer_fd_ = -1;
  int signal_fd_ = -1;
  std::uint64_t watchdog_us_ = 0;
  std::uint64_t watchdog_pings_ = 0;
  LoopTiming timing_;
  std::function<bool()> tagged_;
  std::vector<hal::Micros> tagged_lateness_us_;
};

}  // namespace glider::target
