// SPDX-License-Identifier: Apache-2.0
#pragma once
// The flight log on the target: the loop hands rows to a fixed ring buffer
// (single producer, single consumer, no lock, no allocation) and stamps each
// with UTC (CLOCK_REALTIME: m_present_time); a writer thread formats them
// with the one schema (fw::format_log_fields, the SIL's text), so a slow SD
// card never holds the control loop.
//
// Survival (docs/flight-log.md, "Logs that survive"):
// - whole rows only: rows are formatted into a buffer and written with
//   write(2); a failed or short write is cut back (ftruncate) to the last
//   whole row;
// - fsync every `fsync_every_rows` rows (default 60: a power cut loses at most
//   one minute of a 1 Hz log, and the SD card sees one flush a minute);
// - a full ring refuses the row (the firmware counts it); a full disk loses
//   the rows it cannot take (counted), says so once on stderr (the journal),
//   and the log carries on when space returns;
// - close() ends the file with the trailer `# end: <outcome> rows=N lost=M`.
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include <sys/types.h>

#include "glider/firmware/log/slocum_writer.hpp"
#include "glider/hal/log_record.hpp"
#include "glider/target/loop_clock.hpp"

namespace glider::target {

struct RingLogOptions {
  std::uint32_t fsync_every_rows = 60;
  std::vector<std::pair<std::string, std::string>> metadata;  // `# key: value` lines before the header
  std::FILE* messages = stderr;                               // disk full / recovered, once per episode
  // The loop's clock: each row's m_present_time is the loop clock told in
  // UTC, the UTC at loop time 0 (read once, at the first row) plus the row's
  // loop time: the time the firmware flew by (its timers, `MT:`), so on a
  // bench clock at --time-scale the CSV and the Slocum files describe the
  // flown (simulated) flight, and a step of the system clock (NTP, GPS) never
  // reorders rows (docs/comms.md, the Slocum files' time base). Null: the
  // system clock at the moment of hand-over.
  const LoopClock* loop_clock = nullptr;
  // The system call that writes the file (tests inject a full disk).
  ssize_t (*write_fn)(int fd, const void* data, std::size_t size) = nullptr;
  // The Slocum data files (not owned; null: none): the writer thread hands
  // it every row with its UTC time, so the loop pays nothing more for them.
  fw::SlocumLogger* slocum = nullptr;
};

class RingBufferLog final : public hal::LogSink {
 public:
  static constexpr std::size_t kCapacity = 1024;  // rows: ~17 min at 1 Hz before a stuck writer loses data

  // Start-up: opens (truncates) `path` and writes `# writer: glider-firmware`,
  // the metadata and the header.
  // Throws std::runtime_error naming the file when it cannot.
  explicit RingBufferLog(const std::string& path, RingLogOptions options = {});
  ~RingBufferLog() override;
  RingBufferLog(const RingBufferLog&) = delete;
  RingBufferLog& operator=(const RingBufferLog&) = delete;

  bool write(const hal::FlightLogRecord& record) override;  // loop side: never blocks

  // Writes what is queued, stops the writer, writes the trailer
  // (`outcome`: "complete", "aborted <cause>", "stopped <reason>"), fsyncs and
  // closes; false if a row or the trailer could not be written.
  bool close(std::string_view outcome);
  std::uint64_t rows_written() const { return rows_written_.load(); }
  std::uint64_t rows_refused() const { return rows_refused_.load(); }      // ring full
  std::uint64_t rows_lost_disk() const { return rows_lost_disk_.load(); }  // write failed (disk full)
  std::uint64_t fsyncs() const { return fsyncs_.load(); }
  // The loop time (record.time_us) of the last row handed to the file and the
  // Slocum files (-1: none yet), and a nudge for the writer, which otherwise
  // wakes every 500 ms: the comms task waits for the surfacing's row
  // (fw::comms::LogProgress).
  hal::Micros written_through_us() const { return written_through_us_.load(std::memory_order_acquire); }
  void wake_writer() { wake_.notify_one(); }

 private:
  struct Slot {
    hal::FlightLogRecord record;
    hal::Micros utc_us;
  };
  void drain();
  bool flush_buffer();
  bool write_all(const char* data, std::size_t size);
  void writer_main();

  std::string path_;
  RingLogOptions options_;
  int fd_ = -1;
  std::array<Slot, kCapacity> ring_{};
  std::atomic<std::size_t> head_{0};  // next slot the loop writes
  std::atomic<std::size_t> tail_{0};  // next slot the writer reads
  std::atomic<std::uint64_t> rows_written_{0};
  std::atomic<std::uint64_t> rows_refused_{0};
  std::atomic<std::uint64_t> rows_lost_disk_{0};
  std::atomic<std::uint64_t> fsyncs_{0};
  std::atomic<hal::Micros> written_through_us_{-1};
  // Loop side only: UTC at loop time 0 (with loop_clock), read at the first row.
  bool anchored_ = false;
  hal::Micros utc_at_loop_zero_us_ = 0;
  // Writer thread only:
  std::vector<char> buffer_;
  std::size_t buffered_bytes_ = 0;
  std::uint64_t buffered_rows_ = 0;
  std::uint64_t file_bytes_ = 0;  // always a row boundary
  std::uint64_t rows_since_fsync_ = 0;
  bool disk_failing_ = false;
  std::uint64_t lost_this_episode_ = 0;
  bool io_error_ = false;
  std::mutex wake_mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  bool closed_ = false;
  std::thread writer_;
};

}  // namespace glider::target
