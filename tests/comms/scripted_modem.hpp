// SPDX-License-Identifier: Apache-2.0
#pragma once
// A modem that answers each command line with a scripted reply (or never).
#include <deque>
#include <map>
#include <string>

#include "glider/hal/modem.hpp"

namespace glider::test {

class ScriptedModem final : public hal::Modem {
 public:
  std::map<std::string, std::string> replies;  // command (without CR) -> bytes it makes the modem say
  std::string written;
  std::deque<std::uint8_t> pending;
  hal::Carrier line = hal::Carrier::kUnknown;

  std::size_t read(std::span<std::uint8_t> buffer) override {
    std::size_t n = 0;
    while (n < buffer.size() && !pending.empty()) {
      buffer[n++] = pending.front();
      pending.pop_front();
    }
    return n;
  }
  std::size_t write(std::span<const std::uint8_t> bytes) override {
    for (const std::uint8_t b : bytes) {
      written.push_back(static_cast<char>(b));
      if (b == '\r' || written.ends_with("+++")) {
        std::string command = written.substr(line_start_, written.size() - line_start_ - (b == '\r' ? 1 : 0));
        line_start_ = written.size();
        const auto it = replies.find(command);
        if (it != replies.end()) pending.insert(pending.end(), it->second.begin(), it->second.end());
      }
    }
    return bytes.size();
  }
  hal::Carrier carrier() const override { return line; }

 private:
  std::size_t line_start_ = 0;
};

}  // namespace glider::test
