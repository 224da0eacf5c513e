// SPDX-License-Identifier: Apache-2.0
// The shore's after-surfacing queue (tools/shore/station/after_surfacing_queue.hpp):
// a call hands its glider's health and forecast over and ends at once; one
// glider's jobs run in turn and in order, different gliders side by side;
// shutting down drops (and says so) what never started. Jobs here are fakes
// that block until released, so each property is checked by construction,
// not by timing; every wait is bounded (a failure cannot hang the test).
#include <CppUTest/TestHarness.h>

#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "after_surfacing_queue.hpp"

namespace fs = std::filesystem;
using glider::shore::AfterSurfacingQueue;

namespace {

// Fake work: records starts, blocks each job until released.
class Gate {
 public:
  std::vector<std::string> work(const fs::path& dir) {
    std::unique_lock<std::mutex> lock(mutex_);
    const std::string glider = dir.filename().string();
    const int n = ++started_[glider];
    order_.push_back(glider + "#" + std::to_string(n));
    if (++running_[glider] > 1) overlapped_ = true;
    max_running_ = std::max(max_running_, ++running_total_);
    changed_.notify_all();
    changed_.wait_for(lock, std::chrono::seconds(20), [&] { return released_ > 0; });
    if (released_ > 0) --released_;
    --running_[glider];
    --running_total_;
    changed_.notify_all();
    return {"work " + glider + " " + std::to_string(n)};
  }
  void release(int n) {
    const std::lock_guard<std::mutex> lock(mutex_);
    released_ += n;
    changed_.notify_all();
  }
  // Waits (bounded) until `n` jobs have started in all.
  bool started(std::size_t n) {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, std::chrono::seconds(10), [&] { return order_.size() >= n; });
  }
  std::vector<std::string> order() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return order_;
  }
  bool overlapped() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return overlapped_;
  }
  int max_running() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return max_running_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::string, int> started_, running_;
  std::vector<std::string> order_;
  int running_total_ = 0, max_running_ = 0, released_ = 0;
  bool overlapped_ = false;
};

std::string read(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

fs::path fresh_dir() {
  char pattern[] = "/tmp/glider-after-surfacing-XXXXXX";
  const char* dir = ::mkdtemp(pattern);
  CHECK(dir != nullptr);
  return dir;
}

AfterSurfacingQueue::Work fake(Gate& gate) {
  return [&gate](const fs::path& dir) { return gate.work(dir); };
}

}  // namespace

TEST_GROUP(AfterSurfacingQueue) {
  fs::path root;
  void setup() override { root = fresh_dir(); }
  void teardown() override { fs::remove_all(root); }
  fs::path journal(const std::string& name) {
    const fs::path path = root / (name + ".journal");
    std::ofstream(path) << "call " << name << "\n";
    return path;
  }
};

// The call's thread is not held: submit returns while the work is blocked.
TEST(AfterSurfacingQueue, SubmitReturnsWhileTheWorkRuns) {
  Gate gate;
  AfterSurfacingQueue queue(2, fake(gate));
  const fs::path j = journal("a1");
  queue.submit(root / "a", j);
  CHECK(gate.started(1));  // running, blocked on the gate, and we are here
  gate.release(1);
  queue.drain(10.0);
  CHECK(read(j).find(" * work a 1\n") != std::string::npos);
  CHECK(read(j).rfind("call a1\n", 0) == 0);  // appended, not overwritten
}

// One glider's jobs never overlap and run in the order they came, while
// another glider's job runs beside them.
TEST(AfterSurfacingQueue, OneGliderInTurnOthersBeside) {
  Gate gate;
  AfterSurfacingQueue queue(2, fake(gate));
  queue.submit(root / "a", journal("a1"));
  queue.submit(root / "a", journal("a2"));
  queue.submit(root / "b", journal("b1"));
  CHECK(gate.started(2));  // a#1 and b#1: a#2 waits for a#1 though a worker is free
  {
    const std::vector<std::string> first = gate.order();
    CHECK_EQUAL(2U, first.size());
    CHECK(first[0] != first[1]);
  }
  gate.release(3);
  queue.drain(10.0);
  const std::vector<std::string> order = gate.order();
  CHECK_EQUAL(3U, order.size());
  CHECK_FALSE(gate.overlapped());
  CHECK_EQUAL(2, gate.max_running());
  // a's jobs in order: its first job's note in a1's journal, the second's in a2's.
  CHECK(read(root / "a1.journal").find("work a 1") != std::string::npos);
  CHECK(read(root / "a2.journal").find("work a 2") != std::string::npos);
}

// Shutting down: what never started is dropped, each journal says so; the
// running job ends first (drain joins it), nothing is lost silently.
TEST(AfterSurfacingQueue, DrainDropsWhatNeverStartedAndSaysSo) {
  Gate gate;
  AfterSurfacingQueue queue(1, fake(gate));
  const fs::path j1 = journal("a1"), j2 = journal("a2"), j3 = journal("b1");
  queue.submit(root / "a", j1);
  queue.submit(root / "a", j2);
  queue.submit(root / "b", j3);
  CHECK(gate.started(1));
  gate.release(3);  // a#1 ends; the single worker may start another job before the drain stops it
  queue.drain(0.0);
  // Whatever started ran to its end; whatever did not is noted as not run.
  for (const fs::path& j : {j1, j2, j3}) {
    const std::string text = read(j);
    const bool ran = text.find(" * work ") != std::string::npos;
    const bool dropped = text.find(" * after-surfacing: not run: the shore stopped") != std::string::npos;
    CHECK_TEXT(ran != dropped, (j.string() + ": " + text).c_str());
  }
  CHECK(read(j1).find("work a 1") != std::string::npos);
  // After the drain, new work is refused in its journal.
  const fs::path late = journal("late");
  queue.submit(root / "c", late);
  CHECK(read(late).find("not run: the shore is stopping") != std::string::npos);
}
