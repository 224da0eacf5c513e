// SPDX-License-Identifier: Apache-2.0
#include "glider/target/ring_log.hpp"

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace glider::target {
namespace {

constexpr const char* kHeader =
    "m_present_time,m_depth,m_depth_rate,m_pitch,m_roll,m_heading,m_ballast_pumped,c_ballast_pumped,"
    "m_battpos,c_battpos,c_pitch,m_depth_state,x_yo_count,x_abort_cause,x_loop_overruns";

// NaN (no valid value this cycle) is an empty field.
void put_number(std::FILE* file, double value) {
  if (std::isfinite(value)) std::fprintf(file, "%.9g", value);
  std::fputc(',', file);
}

}  // namespace

RingBufferLog::RingBufferLog(const std::string& path) : file_(std::fopen(path.c_str(), "w")) {
  if (file_ == nullptr) throw std::runtime_error(path + ": cannot open the flight log: " + std::strerror(errno));
  std::fprintf(file_, "# source: glider-firmware on the Linux target\n");
  std::fprintf(file_, "# time: m_present_time is seconds of the monotonic clock\n%s\n", kHeader);
  std::fflush(file_);
  writer_ = std::thread([this] { writer_main(); });
}

RingBufferLog::~RingBufferLog() { close(); }

bool RingBufferLog::write(const hal::FlightLogRecord& record) {
  const std::size_t head = head_.load(std::memory_order_relaxed);
  const std::size_t next = (head + 1) % kCapacity;
  if (next == tail_.load(std::memory_order_acquire)) {
    rows_refused_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  ring_[head] = record;
  head_.store(next, std::memory_order_release);
  return true;
}

void RingBufferLog::drain() {
  std::size_t tail = tail_.load(std::memory_order_relaxed);
  std::uint64_t written = 0;
  while (tail != head_.load(std::memory_order_acquire)) {
    const hal::FlightLogRecord& r = ring_[tail];
    std::fprintf(file_, "%.6f,", hal::to_seconds(r.time_us));
    for (const double value : {r.m_depth, r.m_depth_rate, r.m_pitch, r.m_roll, r.m_heading, r.m_ballast_pumped,
                               r.c_ballast_pumped, r.m_battpos, r.c_battpos, r.c_pitch}) {
      put_number(file_, value);
    }
    std::fprintf(file_, "%d,%d,%d,%u\n", r.m_depth_state, r.x_yo_count, r.x_abort_cause, r.x_loop_overruns);
    tail = (tail + 1) % kCapacity;
    tail_.store(tail, std::memory_order_release);
    ++written;
  }
  if (written > 0) {
    if (std::fflush(file_) != 0 || std::ferror(file_)) io_error_ = true;
    rows_written_ += written;
  }
}

void RingBufferLog::writer_main() {
  std::unique_lock lock(wake_mutex_);
  while (!stopping_) {
    wake_.wait_for(lock, std::chrono::milliseconds(500));
    lock.unlock();
    drain();
    lock.lock();
  }
}

bool RingBufferLog::close() {
  if (file_ == nullptr) return !io_error_;
  {
    std::lock_guard lock(wake_mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  writer_.join();
  drain();  // rows queued after the writer's last pass
  if (std::fclose(file_) != 0) io_error_ = true;
  file_ = nullptr;
  return !io_error_;
}

}  // namespace glider::target
