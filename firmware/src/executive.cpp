// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/executive.hpp"

#include <algorithm>

namespace glider::fw {

Executive::Executive(const hal::Clock& clock, std::span<const TaskSlot> tasks, hal::Micros period_us)
    : clock_(clock),
      tasks_(tasks),
      period_us_(period_us),
      valid_(period_us > 0 && tasks.size() <= kMaxTasks &&
             std::all_of(tasks.begin(), tasks.end(),
                         [](const TaskSlot& slot) { return slot.task != nullptr && slot.every_n_cycles > 0; })) {}

hal::Micros Executive::step() {
  const hal::Micros start = clock_.now_us();
  if (stats_.cycles == 0) {
    next_deadline_us_ = start;
  }
  const hal::Micros lateness = start - next_deadline_us_;
  if (lateness >= period_us_) {
    // Missed at least one whole period: count it and re-anchor the schedule
    // instead of running a burst of catch-up cycles.
    ++stats_.late_starts;
    ++stats_.overruns;
    const hal::Micros missed = lateness / period_us_;
    stats_.skipped_cycles += static_cast<std::uint64_t>(missed);
    next_deadline_us_ += missed * period_us_;
  }

  if (valid_) {
    for (std::size_t i = 0; i < tasks_.size(); ++i) {
      const TaskSlot& slot = tasks_[i];
      if (stats_.cycles % slot.every_n_cycles != 0) {
        continue;
      }
      const hal::Micros task_start = clock_.now_us();
      slot.task->run(task_start);
      const hal::Micros took = clock_.now_us() - task_start;
      TaskStats& task = task_stats_[i];
      ++task.runs;
      task.max_us = std::max(task.max_us, took);
      if (took > slot.budget_us) {
        ++task.overruns;
      }
    }
  }

  const hal::Micros cycle_time = clock_.now_us() - start;
  stats_.max_cycle_us = std::max(stats_.max_cycle_us, cycle_time);
  if (cycle_time > period_us_) {
    ++stats_.overruns;
  }
  ++stats_.cycles;
  next_deadline_us_ += period_us_;
  return next_deadline_us_;
}

}  // namespace glider::fw
