// SPDX-License-Identifier: Apache-2.0
#include <CppUTest/TestHarness.h>

#include <array>

#include "glider/firmware/executive.hpp"

using glider::fw::Executive;
using glider::fw::PeriodicTask;
using glider::fw::TaskSlot;
using glider::hal::Micros;

namespace {

class ManualClock final : public glider::hal::Clock {
 public:
  Micros now_us() const override { return now; }
  Micros now = 0;
};

// A task that records its calls and can pretend to take time.
class WorkTask final : public PeriodicTask {
 public:
  explicit WorkTask(ManualClock& clock) : clock_(clock) {}
  void run(Micros now_us) override {
    ++runs;
    last_run_us = now_us;
    clock_.now += work_us;
  }
  int runs = 0;
  Micros last_run_us = -1;
  Micros work_us = 0;

 private:
  ManualClock& clock_;
};

constexpr Micros kPeriod = 1'000'000;

}  // namespace

TEST_GROUP(Executive) { ManualClock clock; };

TEST(Executive, RunsEachTaskAtItsRate) {
  WorkTask fast(clock);
  WorkTask slow(clock);
  const std::array<TaskSlot, 2> table{{{"fast", &fast, 1, 1000}, {"slow", &slow, 3, 1000}}};
  Executive executive(clock, table, kPeriod);
  CHECK_TRUE(executive.valid());
  for (int i = 0; i < 6; ++i) {
    const Micros next = executive.step();
    LONGS_EQUAL((i + 1) * kPeriod, next);
    clock.now = next;
  }
  LONGS_EQUAL(6, fast.runs);
  LONGS_EQUAL(2, slow.runs);  // cycles 0 and 3
  LONGS_EQUAL(0, executive.stats().overruns);
  LONGS_EQUAL(6, executive.stats().cycles);
}

TEST(Executive, CountsCyclesLongerThanThePeriod) {
  WorkTask task(clock);
  const std::array<TaskSlot, 1> table{{{"work", &task, 1, 200'000}}};
  Executive executive(clock, table, kPeriod);
  task.work_us = 300'000;  // over its budget, within the period
  clock.now = executive.step();
  LONGS_EQUAL(0, executive.stats().overruns);
  LONGS_EQUAL(1, executive.task_stats(0).overruns);
  LONGS_EQUAL(300'000, executive.task_stats(0).max_us);
  task.work_us = 1'500'000;  // longer than the period
  executive.step();
  LONGS_EQUAL(1, executive.stats().overruns);
  LONGS_EQUAL(1'500'000, executive.stats().max_cycle_us);
}

TEST(Executive, LateStartIsCountedAndTheScheduleReanchored) {
  WorkTask task(clock);
  const std::array<TaskSlot, 1> table{{{"work", &task, 1, 1000}}};
  Executive executive(clock, table, kPeriod);
  clock.now = executive.step();           // deadline for cycle 1: 1 s
  clock.now = 3 * kPeriod + kPeriod / 2;  // woke up 2.5 periods late
  const Micros next = executive.step();
  LONGS_EQUAL(1, executive.stats().late_starts);
  LONGS_EQUAL(2, executive.stats().skipped_cycles);
  LONGS_EQUAL(4 * kPeriod, next);  // next deadline on the original grid
  LONGS_EQUAL(clock.now, task.last_run_us);
}

TEST(Executive, RejectsABadTable) {
  const std::array<TaskSlot, 1> table{{{"none", nullptr, 1, 1000}}};
  Executive executive(clock, table, kPeriod);
  CHECK_FALSE(executive.valid());
  executive.step();  // must not crash, runs nothing
  LONGS_EQUAL(1, executive.stats().cycles);
}
