// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/comms/at_driver.hpp"

#include <cstring>
#include <string_view>

namespace glider::fw::comms {
namespace {

// A whole decimal number (no sign, at most 7 digits), or -1.
std::int32_t parse_count(std::string_view text) {
  if (text.empty() || text.size() > 7) return -1;
  std::int32_t value = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return -1;
    value = value * 10 + (c - '0');
  }
  return value;
}

}  // namespace

const char* to_string(AtResult result) {
  switch (result) {
    case AtResult::kPending:
      return "pending";
    case AtResult::kOk:
      return "OK";
    case AtResult::kError:
      return "ERROR";
    case AtResult::kConnect:
      return "CONNECT";
    case AtResult::kNoCarrier:
      return "NO CARRIER";
    case AtResult::kBusy:
      return "BUSY";
    case AtResult::kNoAnswer:
      return "NO ANSWER";
    case AtResult::kNoDialtone:
      return "NO DIALTONE";
    case AtResult::kTimeout:
      return "timeout";
  }
  return "?";
}

bool AtDriver::start(const char* command, hal::Micros now_us, hal::Micros timeout_us, bool raw) {
  const std::size_t length = std::strlen(command);
  if (length + 1 > kMaxCommand) return false;
  std::memcpy(command_.data(), command, length);
  command_size_ = length;
  std::array<std::uint8_t, kMaxCommand> out{};
  std::memcpy(out.data(), command, length);
  std::size_t total = length;
  if (!raw) out[total++] = '\r';
  // Whatever the modem said before this command is stale: drop it.
  line_size_ = 0;
  line_cut_ = false;
  after_connect_size_ = 0;
  std::array<std::uint8_t, kReadPerPoll> stale{};
  (void)modem_.read(stale);
  if (modem_.write(std::span<const std::uint8_t>(out.data(), total)) != total) return false;
  busy_ = true;
  deadline_us_ = now_us + timeout_us;
  return true;
}

AtResult AtDriver::classify_line() {
  const std::string_view line(line_.data(), line_size_);
  const bool cut = line_cut_;
  line_size_ = 0;
  line_cut_ = false;
  if (line.empty()) return AtResult::kPending;
  if (cut) {
    ++overlong_;
    return AtResult::kPending;
  }
  if (line == std::string_view(command_.data(), command_size_)) return AtResult::kPending;  // echo (E1)
  if (line == "OK") return AtResult::kOk;
  if (line == "ERROR") return AtResult::kError;
  if (line == "NO CARRIER") return AtResult::kNoCarrier;
  if (line == "BUSY") return AtResult::kBusy;
  if (line == "NO ANSWER") return AtResult::kNoAnswer;
  if (line == "NO DIALTONE") return AtResult::kNoDialtone;
  if (line == "CONNECT") return AtResult::kConnect;
  if (line.starts_with("CONNECT ")) {
    const std::int32_t rate = parse_count(line.substr(8));
    if (rate < 0) {
      ++malformed_;
      return AtResult::kPending;
    }
    connect_rate_ = rate;
    return AtResult::kConnect;
  }
  if (line.starts_with("+CSQ:")) {
    std::string_view value = line.substr(5);
    while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
    const std::int32_t csq = parse_count(value);
    if (csq < 0 || csq > 5) {
      ++malformed_;
      return AtResult::kPending;
    }
    csq_ = csq;
    return AtResult::kPending;
  }
  ++malformed_;
  return AtResult::kPending;
}

AtResult AtDriver::poll(hal::Micros now_us) {
  if (!busy_) return AtResult::kPending;
  std::array<std::uint8_t, kReadPerPoll> chunk{};
  const std::size_t n = modem_.read(chunk);
  for (std::size_t i = 0; i < n; ++i) {
    const char c = static_cast<char>(chunk[i]);
    if (c == '\r' || c == '\n') {
      const AtResult result = classify_line();
      if (result == AtResult::kPending) continue;
      busy_ = false;
      if (result == AtResult::kConnect) {
        // The call's bytes may follow in the same read; keep them for the dialog.
        std::size_t start = i + 1;
        if (start < n && chunk[start] == '\n' && c == '\r') ++start;
        after_connect_size_ = n - start;
        std::memcpy(after_connect_.data(), chunk.data() + start, after_connect_size_);
      }
      return result;
    }
    if (line_size_ < kMaxLine) {
      line_[line_size_++] = c;
    } else {
      line_cut_ = true;
    }
  }
  if (now_us >= deadline_us_) {
    busy_ = false;
    ++timeouts_;
    return AtResult::kTimeout;
  }
  return AtResult::kPending;
}

}  // namespace glider::fw::comms
