// SPDX-License-Identifier: Apache-2.0
#include "glider/target/ring_log.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <stdexcept>

#include "glider/firmware/log/log_text.hpp"

namespace glider::target {
namespace {

constexpr std::size_t kBufferBytes = std::size_t{64} * 1024;

hal::Micros utc_now_us() {
  timespec t{};
  clock_gettime(CLOCK_REALTIME, &t);
  return static_cast<hal::Micros>(t.tv_sec) * hal::kMicrosPerSecond + t.tv_nsec / 1000;
}

}  // namespace

RingBufferLog::RingBufferLog(const std::string& path, RingLogOptions options)
    : path_(path), options_(std::move(options)) {
  if (options_.write_fn == nullptr) options_.write_fn = ::write;
  if (options_.fsync_every_rows == 0) options_.fsync_every_rows = 1;
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error(path + ": cannot open the flight log: " + std::strerror(errno));
  // First line: the writer, so a log without the trailer reads as cut short
  // (docs/flight-log.md: our writers always end a finished flight with one).
  std::string head = "# writer: glider-firmware\n";
  for (const auto& [key, value] : options_.metadata)
    head.append("# ").append(key).append(": ").append(value).append("\n");
  head += fw::log_header() + "\n";
  if (!write_all(head.data(), head.size()) || ::fsync(fd_) != 0) {
    const std::string error = std::strerror(errno);
    ::close(fd_);
    throw std::runtime_error(path + ": cannot write the flight log's header: " + error);
  }
  file_bytes_ = head.size();
  buffer_.resize(kBufferBytes);
  writer_ = std::thread([this] { writer_main(); });
}

RingBufferLog::~RingBufferLog() { close("stopped destroyed"); }

bool RingBufferLog::write(const hal::FlightLogRecord& record) {
  const std::size_t head = head_.load(std::memory_order_relaxed);
  const std::size_t next = (head + 1) % kCapacity;
  if (next == tail_.load(std::memory_order_acquire)) {
    rows_refused_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  hal::Micros utc_us = utc_now_us();
  if (options_.loop_clock != nullptr) {
    if (!anchored_) {
      // The first row's cycle start in UTC (back from now in real time: the
      // loop clock may run faster), less its loop time.
      utc_at_loop_zero_us_ =
          utc_us - (monotonic_now_us() - options_.loop_clock->to_monotonic_us(record.time_us)) - record.time_us;
      anchored_ = true;
    }
    utc_us = utc_at_loop_zero_us_ + record.time_us;
  }
  ring_[head] = Slot{record, utc_us};
  head_.store(next, std::memory_order_release);
  return true;
}

bool RingBufferLog::write_all(const char* data, std::size_t size) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = options_.write_fn(fd_, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// The buffer holds whole rows only. A failed write loses those rows (counted)
// and cuts the file back to its last whole row.
bool RingBufferLog::flush_buffer() {
  if (buffered_rows_ == 0) return true;
  const bool ok = write_all(buffer_.data(), buffered_bytes_);
  const int error = errno;
  if (ok) {
    file_bytes_ += buffered_bytes_;
    rows_written_ += buffered_rows_;
    rows_since_fsync_ += buffered_rows_;
    if (disk_failing_) {
      std::fprintf(options_.messages, "glider-firmware: flight log %s: writing again (%llu rows were lost)\n",
                   path_.c_str(), static_cast<unsigned long long>(lost_this_episode_));
      std::fflush(options_.messages);
      disk_failing_ = false;
    }
  } else {
    if (::ftruncate(fd_, static_cast<off_t>(file_bytes_)) != 0) io_error_ = true;
    rows_lost_disk_ += buffered_rows_;
    if (!disk_failing_) {
      std::fprintf(options_.messages,
                   "glider-firmware: flight log %s: %s: rows are lost (counted) until it can write again\n",
                   path_.c_str(), std::strerror(error));
      std::fflush(options_.messages);
      disk_failing_ = true;
      lost_this_episode_ = 0;
    }
    lost_this_episode_ += buffered_rows_;
  }
  buffered_bytes_ = 0;
  buffered_rows_ = 0;
  if (ok && rows_since_fsync_ >= options_.fsync_every_rows) {
    if (::fsync(fd_) == 0) fsyncs_.fetch_add(1, std::memory_order_relaxed);
    rows_since_fsync_ = 0;
  }
  return ok;
}

void RingBufferLog::drain() {
  std::size_t tail = tail_.load(std::memory_order_relaxed);
  while (tail != head_.load(std::memory_order_acquire)) {
    // At least every fsync_every_rows rows reach the card (flush_buffer fsyncs).
    if (buffered_rows_ >= options_.fsync_every_rows || buffer_.size() - buffered_bytes_ < fw::kLogFieldsMaxChars) {
      flush_buffer();
    }
    const Slot& slot = ring_[tail];
    if (options_.slocum != nullptr) options_.slocum->write(slot.record, slot.utc_us);
    const std::size_t n = fw::format_log_fields(slot.record, slot.utc_us, buffer_.data() + buffered_bytes_,
                                                buffer_.size() - buffered_bytes_);
    if (n > 0) {
      buffer_[buffered_bytes_ + n - 1] = '\n';  // the last field's ',' ends the row
      buffered_bytes_ += n;
      ++buffered_rows_;
    } else {
      rows_lost_disk_.fetch_add(1, std::memory_order_relaxed);  // cannot happen: a row fits kLogFieldsMaxChars
    }
    written_through_us_.store(slot.record.time_us, std::memory_order_release);
    tail = (tail + 1) % kCapacity;
    tail_.store(tail, std::memory_order_release);
  }
  flush_buffer();
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

bool RingBufferLog::close(std::string_view outcome) {
  if (closed_) return !io_error_;
  closed_ = true;
  {
    std::lock_guard lock(wake_mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  writer_.join();
  drain();  // rows queued after the writer's last pass
  char trailer[256];
  const std::size_t n = fw::format_log_trailer(outcome, rows_written_.load(),
                                               rows_refused_.load() + rows_lost_disk_.load(), trailer, sizeof trailer);
  bool ok = !io_error_ && rows_lost_disk_.load() == 0;
  if (n == 0 || !write_all(trailer, n)) {
    if (::ftruncate(fd_, static_cast<off_t>(file_bytes_)) != 0) io_error_ = true;
    ok = false;
  }
  if (::fsync(fd_) != 0) ok = false;
  if (::close(fd_) != 0) ok = false;
  fd_ = -1;
  return ok;
}

}  // namespace glider::target
