// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>
#include <cstdint>
#include <span>

#include "glider/hal/clock.hpp"

namespace glider::fw {

class PeriodicTask {
 public:
  virtual ~PeriodicTask() = default;
  virtual void run(hal::Micros now_us) = 0;
};

// One row of the executive's task table.
struct TaskSlot {
  const char* name;
  PeriodicTask* task;
  std::uint32_t every_n_cycles;  // 1 = every cycle
  hal::Micros budget_us;         // execution time above this counts an overrun
};

struct TaskStats {
  std::uint64_t runs = 0;
  std::uint32_t overruns = 0;
  hal::Micros max_us = 0;
};

struct ExecutiveStats {
  std::uint64_t cycles = 0;
  std::uint32_t overruns = 0;     // cycles that ran longer than the period
  std::uint32_t late_starts = 0;  // cycles that started a period or more late
  std::uint64_t skipped_cycles = 0;
  hal::Micros max_cycle_us = 0;
};

// Fixed-rate, table-driven, single-threaded executive (in the spirit of
// ArduPilot's AP_Scheduler). The platform calls step() once per period; on
// Linux a timerfd with absolute deadlines does that, in SIL the lockstep
// runner. Time comes only from the HAL clock; nothing here allocates.
class Executive {
 public:
  static constexpr std::size_t kMaxTasks = 16;

  // Control period. 1 Hz: the glider's fastest controlled mode is the pitch
  // pendulum (period ~15 s for a SLOCUM, see model/), the battery slide moves
  // ~0.05 in/s and depth changes 0.2 m per second, so 1 Hz gives >10 samples
  // per pitch period and 0.2 m depth resolution at the inflections while
  // keeping the computer asleep most of the time (energy is range).
  static constexpr hal::Micros kDefaultPeriodUs = 1'000'000;

  // `tasks` must outlive the executive and hold at most kMaxTasks rows.
  Executive(const hal::Clock& clock, std::span<const TaskSlot> tasks, hal::Micros period_us = kDefaultPeriodUs);

  bool valid() const { return valid_; }

  // Runs the tasks due in this cycle and returns the absolute deadline of the
  // next cycle (for the platform's sleep).
  hal::Micros step();

  hal::Micros period_us() const { return period_us_; }
  const ExecutiveStats& stats() const { return stats_; }
  const TaskStats& task_stats(std::size_t index) const { return task_stats_[index]; }

 private:
  const hal::Clock& clock_;
  std::span<const TaskSlot> tasks_;
  hal::Micros period_us_;
  bool valid_;
  hal::Micros next_deadline_us_ = 0;
  ExecutiveStats stats_{};
  std::array<TaskStats, kMaxTasks> task_stats_{};
};

}  // namespace glider::fw
