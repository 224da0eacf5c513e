// SPDX-License-Identifier: Apache-2.0
#pragma once
// The flight log on the target: the loop hands rows to a fixed ring buffer
// (single producer, single consumer, no lock, no allocation) and a writer
// thread turns them into CSV (docs/flight-log.md columns, m_present_time in
// seconds since start) and flushes them, so a slow SD card never holds the
// control loop. A full ring refuses the row (the firmware counts it).
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

#include "glider/hal/log_record.hpp"

namespace glider::target {

class RingBufferLog final : public hal::LogSink {
 public:
  static constexpr std::size_t kCapacity = 1024;  // rows: ~17 min at 1 Hz before a stuck writer loses data

  // Start-up: opens (truncates) `path` and writes the header. Throws
  // std::runtime_error naming the file when it cannot.
  explicit RingBufferLog(const std::string& path);
  ~RingBufferLog() override;

  bool write(const hal::FlightLogRecord& record) override;  // loop side: never blocks

  // Writes what is queued, stops the writer, closes the file; false if a
  // write failed on the way.
  bool close();
  std::uint64_t rows_written() const { return rows_written_.load(); }
  std::uint64_t rows_refused() const { return rows_refused_.load(); }

 private:
  void drain();
  void writer_main();

  std::FILE* file_;
  std::array<hal::FlightLogRecord, kCapacity> ring_{};
  std::atomic<std::size_t> head_{0};  // next slot the loop writes
  std::atomic<std::size_t> tail_{0};  // next slot the writer reads
  std::atomic<std::uint64_t> rows_written_{0};
  std::atomic<std::uint64_t> rows_refused_{0};
  std::atomic<bool> io_error_{false};
  std::mutex wake_mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread writer_;
};

}  // namespace glider::target
