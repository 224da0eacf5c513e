// SPDX-License-Identifier: Apache-2.0
#include "after_surfacing_queue.hpp"

#include <chrono>
#include <cstdio>
#include <utility>

#include "session_journal.hpp"

namespace glider::shore {
namespace {

void note_all(const std::filesystem::path& journal, const std::vector<std::string>& notes) {
  try {
    for (const std::string& note : notes) SessionJournal::append(journal, '*', note);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "glider-shore: %s: %s\n", journal.c_str(), error.what());
  }
}

}  // namespace

AfterSurfacingQueue::AfterSurfacingQueue(int workers, Work work) : work_(std::move(work)) {
  for (int i = 0; i < workers; ++i) threads_.emplace_back([this] { worker(); });
}

AfterSurfacingQueue::~AfterSurfacingQueue() { drain(0.0); }

void AfterSurfacingQueue::submit(const std::filesystem::path& glider_dir, const std::filesystem::path& journal) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!stopping_) {
      queued_.push_back({glider_dir.lexically_normal(), journal});
      changed_.notify_all();
      return;
    }
  }
  note_all(journal, {"after-surfacing: not run: the shore is stopping"});
}

bool AfterSurfacingQueue::take_runnable(Job& job) {
  for (auto it = queued_.begin(); it != queued_.end(); ++it) {
    if (running_.count(it->glider_dir) != 0) continue;
    job = std::move(*it);
    queued_.erase(it);
    running_.insert(job.glider_dir);
    return true;
  }
  return false;
}

void AfterSurfacingQueue::worker() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    Job job;
    changed_.wait(lock, [&] { return stopping_ || take_runnable(job); });
    if (job.glider_dir.empty()) return;  // stopping, nothing taken
    lock.unlock();
    note_all(job.journal, work_(job.glider_dir));
    lock.lock();
    running_.erase(job.glider_dir);
    changed_.notify_all();  // the glider's next job, and drain(), wait for this
  }
}

void AfterSurfacingQueue::drain(double seconds) {
  std::deque<Job> dropped;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    if (threads_.empty()) return;  // drained already
    changed_.wait_for(lock, std::chrono::duration<double>(seconds),
                      [this] { return queued_.empty() && running_.empty(); });
    stopping_ = true;
    dropped.swap(queued_);
    changed_.notify_all();
  }
  for (std::thread& thread : threads_) thread.join();  // a running job ends first
  threads_.clear();
  for (const Job& job : dropped) {
    std::fprintf(stderr, "glider-shore: %s: after-surfacing work not run: the shore stopped\n", job.glider_dir.c_str());
    note_all(job.journal, {"after-surfacing: not run: the shore stopped; the next call's health reads this call's "
                           "data too"});
  }
}

}  // namespace glider::shore
