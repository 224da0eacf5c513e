// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the console's `send`/`s`, `zs` and `zr` commands hand to the file
// transfer engine (Zmodem, branch zmodem, implements it). The console picks
// the files (globs, -num=); the engine moves them over the call's stream,
// a bounded slice per control cycle, and says when it is done. Tests drive
// the console with a fake engine.
#include <cstddef>
#include <cstdint>
#include <span>

#include "glider/firmware/comms/byte_stream.hpp"
#include "glider/hal/time.hpp"

namespace glider::fw::comms {

constexpr std::size_t kMaxFileName = 64;      // a Slocum 8.3 name or a long segment name
constexpr std::size_t kMaxFilesPerSend = 32;  // one command moves at most this many files

struct FileName {
  char text[kMaxFileName] = {};
};

enum class TransferState : std::int32_t {
  kIdle = 0,
  kRunning = 1,
  kDone = 2,    // every file moved and acknowledged
  kFailed = 3,  // gave up (retries exhausted, cancelled, carrier lost)
};

struct TransferProgress {
  TransferState state = TransferState::kIdle;
  std::int32_t files_done = 0;
  std::int32_t files_failed = 0;
  std::uint64_t bytes = 0;
};

class FileTransfer {
 public:
  virtual ~FileTransfer() = default;
  // The vehicle's files a send may pick from, oldest first (the last ones
  // are the newest: `-num=N` sends the newest N that match).
  virtual std::size_t file_count() const = 0;
  virtual const char* file_name(std::size_t index) const = 0;
  // Reads the vehicle's file list again (a send command does this first:
  // new segments were closed since the last one).
  virtual void list_files() {}
  // Starts sending these files to shore (send, s, zs). False: refused (busy).
  virtual bool begin_send(std::span<const FileName> files) = 0;
  // Starts receiving files from shore (zr); a received .ma/.mi is only
  // applied by the mission layer after validation.
  virtual bool begin_receive() = 0;
  // One bounded slice of the transfer over the stream; called every cycle
  // while running.
  virtual TransferProgress poll(hal::Micros now_us, ByteStream& stream) = 0;
  // The files the last receive published complete (full paths), for the
  // mission layer to validate a .ma/.mi before it is used.
  virtual std::size_t received_count() const { return 0; }
  virtual const char* received_path(std::size_t /*index*/) const { return ""; }
  // Carrier lost or the pilot gave up: stop at once (a partial file is never published).
  virtual void cancel() = 0;
};

}  // namespace glider::fw::comms
