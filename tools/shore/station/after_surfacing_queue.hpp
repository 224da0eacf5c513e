// SPDX-License-Identifier: Apache-2.0
#pragma once
// The shore's after-surfacing work (after_surfacing.hpp: health, then the
// forecast) runs here, off the call's thread. A call ends, and gives back its
// slot (--max-calls), as soon as its surfacing event is written: a fleet
// surfacing together is not refused because health and forecasts of earlier
// calls are still running (they take about a second each).
//
// One glider's jobs run one at a time, in the order they came: both read and
// write the same health/ and forecast/, and overlapping, an older view could
// be written last; one at a time, each reads the folder when its turn comes
// and the last leaves the newest. Different gliders run side by side, on up
// to `workers` threads. Each job's notes go to the journal of the call that
// queued it ('*' lines), as if the call had written them itself.
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace glider::shore {

class AfterSurfacingQueue {
 public:
  // The work done for one glider folder; returns one note per step. Never
  // throws (after_surfacing's contract); tests give their own.
  using Work = std::function<std::vector<std::string>(const std::filesystem::path& glider_dir)>;

  AfterSurfacingQueue(int workers, Work work);
  ~AfterSurfacingQueue();  // drain(0)
  AfterSurfacingQueue(const AfterSurfacingQueue&) = delete;
  AfterSurfacingQueue& operator=(const AfterSurfacingQueue&) = delete;

  // Queues the work for `glider_dir`; its notes are appended to `journal`.
  // Returns at once. After drain() the job is refused: noted in the journal.
  void submit(const std::filesystem::path& glider_dir, const std::filesystem::path& journal);

  // Shutting down: waits up to `seconds` for the queued work, then drops the
  // jobs not started (each journal says so; the glider's next call's health
  // reads their data too) and waits for the running ones to end.
  void drain(double seconds);

 private:
  struct Job {
    std::filesystem::path glider_dir, journal;
  };
  void worker();
  // Takes the first queued job whose glider has no job running; false if none.
  bool take_runnable(Job& job);

  Work work_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> queued_;
  std::set<std::filesystem::path> running_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace glider::shore
