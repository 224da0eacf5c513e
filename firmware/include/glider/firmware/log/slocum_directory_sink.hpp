// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Slocum files in a directory (POSIX): glider-sil's --slocum-dir and
// glider-firmware's log directory. A file is written with write(2) in whole
// buffers; a failed or short write is cut back (ftruncate) to the file's
// last whole buffer, so the file always ends on a cycle boundary; close()
// fsyncs. No allocation after construction.
#include <array>
#include <cstdint>
#include <mutex>
#include <string>

#include "glider/firmware/log/slocum_sink.hpp"
#include "glider/hal/log_record.hpp"
#include "glider/hal/time.hpp"

namespace glider::fw {

class SlocumDirectorySink final : public SlocumSink {
 public:
  // Start-up: creates `directory` and its cac/ folder if needed. ok() false
  // (with error()) when it cannot.
  explicit SlocumDirectorySink(const std::string& directory);
  ~SlocumDirectorySink() override;
  SlocumDirectorySink(const SlocumDirectorySink&) = delete;
  SlocumDirectorySink& operator=(const SlocumDirectorySink&) = delete;

  bool open(int slot, const char* name) override;
  bool write(int slot, const char* data, std::size_t size) override;
  bool close(int slot) override;

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  const std::string& directory() const { return directory_; }
  std::uint64_t write_failures() const { return write_failures_; }
  // True while `name` (a file name in the directory) is open for writing:
  // a transfer must not send a segment that is still growing. Safe from
  // another thread (the target writes from its log thread): the names are
  // under a mutex held only to copy or compare them, never across I/O.
  bool is_open(const char* name) const;

 private:
  std::string directory_;
  std::array<char, 4096> path_{};
  std::array<int, kSlots> fd_{};
  std::array<std::uint64_t, kSlots> length_{};
  mutable std::mutex names_mutex_;
  std::array<std::array<char, 128>, kSlots> open_name_{};  // bytes known written: a buffer boundary
  std::uint64_t write_failures_ = 0;
  std::string error_;
};

// The numbers of a new mission's files, from the files already in
// `directory` (start-up): the long name's <mission> is one more than the
// highest of `vehicle`'s missions started the same UTC day (0 if none); the
// 8.3 mission number one more than the highest in the headers
// (the8x3_filename) of the vehicle's files there, LZ4 forms included (0 if none).
struct SlocumMissionNumbers {
  int mission_of_day = 0;
  int mission_number = 0;
};
SlocumMissionNumbers next_slocum_mission(const std::string& directory, const std::string& vehicle,
                                         hal::Micros start_utc_us);

}  // namespace glider::fw
