// SPDX-License-Identifier: Apache-2.0
#include "glider/target/realtime_loop.hpp"

#include <poll.h>
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/signalfd.h>
#include <sys/timerfd.h>
#include <systemd/sd-daemon.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace glider::target {
namespace {

std::string errno_text() { return std::strerror(errno); }

}  // namespace

std::string apply_realtime(const RealtimeOptions& options) {
  std::string warning;
  if (options.sched_fifo) {
    sched_param param{};
    param.sched_priority = options.priority;
    if (sched_setscheduler(0, SCHED_FIFO, &param) != 0) {
      warning += "SCHED_FIFO " + std::to_string(options.priority) + " not set (" + errno_text() +
                 "; needs CAP_SYS_NICE or LimitRTPRIO): running SCHED_OTHER. ";
    }
  }
  if (options.lock_memory && mlockall(MCL_CURRENT | MCL_FUTURE) != 0) {
    warning += "mlockall not done (" + errno_text() + "; needs CAP_IPC_LOCK or LimitMEMLOCK): pages may fault. ";
  }
  return warning;
}

sigset_t stop_signal_set() {
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGTERM);
  sigaddset(&stop_signals, SIGINT);
  return stop_signals;
}

void block_stop_signals() {
  const sigset_t stop_signals = stop_signal_set();
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
}

RealtimeLoop::RealtimeLoop(fw::Executive& executive, const LoopClock& clock, const RealtimeOptions& options,
                           std::FILE* log)
    : executive_(executive), clock_(clock), options_(options), log_(log) {
  const sigset_t stop_signals = stop_signal_set();
  if (pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr) != 0) throw std::runtime_error("pthread_sigmask failed");
  signal_fd_ = signalfd(-1, &stop_signals, SFD_NONBLOCK | SFD_CLOEXEC);
  if (signal_fd_ < 0) throw std::runtime_error("signalfd: " + errno_text());
  timer_fd_ = timerfd_create(CLOCK_MONOTONIC, TFD_CLOEXEC);
  if (timer_fd_ < 0) throw std::runtime_error("timerfd_create: " + errno_text());
  // Under systemd with WatchdogSec=, WATCHDOG_USEC says how often to ping.
  std::uint64_t usec = 0;
  if (sd_watchdog_enabled(0, &usec) > 0) watchdog_us_ = usec;
  tagged_lateness_us_.reserve(kTaggedCapacity);
}

RealtimeLoop::~RealtimeLoop() {
  if (timer_fd_ >= 0) close(timer_fd_);
  if (signal_fd_ >= 0) close(signal_fd_);
}

// Sleeps until the absolute deadline (or a stop signal). The one place the
// loop blocks, by design.
bool RealtimeLoop::wait_until(hal::Micros deadline_us, bool& signalled) {
  itimerspec spec{};
  spec.it_value.tv_sec = deadline_us / hal::kMicrosPerSecond;
  spec.it_value.tv_nsec = (deadline_us % hal::kMicrosPerSecond) * 1000;
  if (spec.it_value.tv_sec == 0 && spec.it_value.tv_nsec == 0) spec.it_value.tv_nsec = 1;  // 0 would disarm
  if (timerfd_settime(timer_fd_, TFD_TIMER_ABSTIME, &spec, nullptr) != 0) return false;
  pollfd fds[2] = {{timer_fd_, POLLIN, 0}, {signal_fd_, POLLIN, 0}};
  while (true) {
    const int ready = poll(fds, 2, -1);
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) return false;
    if (fds[1].revents & POLLIN) {
      signalfd_siginfo info{};
      if (read(signal_fd_, &info, sizeof info) == static_cast<ssize_t>(sizeof info)) signalled = true;
      return true;
    }
    if (fds[0].revents & POLLIN) {
      std::uint64_t expirations = 0;
      if (read(timer_fd_, &expirations, sizeof expirations) != static_cast<ssize_t>(sizeof expirations)) return false;
      return true;
    }
  }
}

StopReason RealtimeLoop::run(const std::function<bool()>& done, const std::function<bool()>& healthy,
                             std::uint64_t max_cycles) {
  sd_notify(0, "READY=1\nSTATUS=flying");
  // Timing is measured on CLOCK_MONOTONIC; the executive's deadlines are loop
  // time (the same unless --time-scale).
  const hal::Micros period = static_cast<hal::Micros>(static_cast<double>(executive_.period_us()) / clock_.scale());
  hal::Micros deadline = monotonic_now_us();
  hal::Micros next_stats = deadline + options_.stats_every_us;
  hal::Micros last_ping = 0;
  char line[256];
  StopReason reason = StopReason::kCycleLimit;  // unless done, signalled or failed first
  for (std::uint64_t cycle = 0; max_cycles == 0 || cycle < max_cycles; ++cycle) {
    const hal::Micros woke = monotonic_now_us();
    if (tagged_ && tagged_lateness_us_.size() < kTaggedCapacity && tagged_()) {
      tagged_lateness_us_.push_back(std::max<hal::Micros>(woke - deadline, 0));
    }
    const hal::Micros next_deadline = executive_.step();
    const hal::Micros worked = monotonic_now_us() - woke;
    timing_.record(woke - deadline, worked, period);
    if (watchdog_us_ > 0 && healthy() && woke - last_ping >= static_cast<hal::Micros>(watchdog_us_ / 4)) {
      sd_notify(0, "WATCHDOG=1");
      ++watchdog_pings_;
      last_ping = woke;
    }
    if (woke >= next_stats) {
      timing_.format(line, sizeof line);
      std::fprintf(log_, "glider-firmware: loop: %s\n", line);
      std::fflush(log_);
      next_stats += options_.stats_every_us;
    }
    if (done()) {
      reason = StopReason::kDone;
      break;
    }
    deadline = clock_.to_monotonic_us(next_deadline);
    bool signalled = false;
    if (!wait_until(deadline, signalled)) {
      std::fprintf(log_, "glider-firmware: loop: timer failed (%s), stopping\n", errno_text().c_str());
      reason = StopReason::kError;
      break;
    }
    if (signalled) {
      reason = StopReason::kSignal;
      break;
    }
  }
  sd_notify(0, "STOPPING=1");
  return reason;
}

}  // namespace glider::target
