// SPDX-License-Identifier: Apache-2.0
#pragma once
// One Hayes AT command at a time over the modem's serial line: send it, read
// the reply lines as they arrive (bounded per call), finish on a final
// result code or the command's timeout. Malformed lines are counted and
// skipped (a final code is still needed), an overlong line is cut, a modem
// that never answers times out. Never blocks, never allocates.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "glider/hal/modem.hpp"
#include "glider/hal/time.hpp"

namespace glider::fw::comms {

enum class AtResult : std::int32_t {
  kPending = 0,  // still waiting
  kOk,
  kError,
  kConnect,  // data mode: the bytes after it are the call's
  kNoCarrier,
  kBusy,
  kNoAnswer,
  kNoDialtone,
  kTimeout,
};

const char* to_string(AtResult result);

class AtDriver {
 public:
  static constexpr std::size_t kMaxLine = 80;       // longer reply lines are cut (and counted)
  static constexpr std::size_t kReadPerPoll = 256;  // bytes taken from the modem per poll
  static constexpr std::size_t kMaxCommand = 48;    // ATD + a long number fits

  explicit AtDriver(hal::Modem& modem) : modem_(modem) {}

  // Sends `command` followed by CR (or raw, for the "+++" escape) and starts
  // its timeout. False when the command does not fit or the modem would not
  // take it whole (a later poll() says kTimeout only for a sent command).
  bool start(const char* command, hal::Micros now_us, hal::Micros timeout_us, bool raw = false);
  // Reads what has arrived and returns the final result once there is one.
  AtResult poll(hal::Micros now_us);
  bool busy() const { return busy_; }

  // Set when the reply carried them (else -1).
  std::int32_t signal_quality() const { return csq_; }  // +CSQ:n, 0..5
  std::int32_t connect_rate() const { return connect_rate_; }
  // Bytes that followed CONNECT in the same read: the call's first bytes.
  std::span<const std::uint8_t> data_after_connect() const { return {after_connect_.data(), after_connect_size_}; }
  void clear_data_after_connect() { after_connect_size_ = 0; }

  std::uint32_t malformed_lines() const { return malformed_; }
  std::uint32_t overlong_lines() const { return overlong_; }
  std::uint32_t timeouts() const { return timeouts_; }

 private:
  AtResult classify_line();

  hal::Modem& modem_;
  bool busy_ = false;
  hal::Micros deadline_us_ = 0;
  std::array<char, kMaxCommand> command_{};
  std::size_t command_size_ = 0;
  std::array<char, kMaxLine + 1> line_{};
  std::size_t line_size_ = 0;
  bool line_cut_ = false;
  std::int32_t csq_ = -1;
  std::int32_t connect_rate_ = -1;
  std::array<std::uint8_t, kReadPerPoll> after_connect_{};
  std::size_t after_connect_size_ = 0;
  std::uint32_t malformed_ = 0;
  std::uint32_t overlong_ = 0;
  std::uint32_t timeouts_ = 0;
};

}  // namespace glider::fw::comms
