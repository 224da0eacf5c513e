// SPDX-License-Identifier: Apache-2.0
#pragma once
// The glider's Iridium modem as the plant serves it: a pseudo-terminal that
// speaks Hayes AT (AT, ATE0/ATE1, AT+CSQ, ATD<number>, +++ with guard time,
// ATH) and, once dialled, bridges the call to a shore station over TCP (a
// RUDICS call arrives at the shore as a TCP connection: docs/comms.md). The
// shore hanging up is "NO CARRIER" on the line. Every number reaches the
// one --shore address. Driven from the plant's poll loop; never blocks
// (the loopback connect is the one short wait, at ATD).
#include <poll.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pty_device.hpp"

namespace glider::plant {

struct ModemBridgeStats {
  std::uint64_t calls = 0;
  std::uint64_t connects = 0;
  std::uint64_t bytes_up = 0;    // glider -> shore
  std::uint64_t bytes_down = 0;  // shore -> glider
};

class ModemBridge {
 public:
  // `link`: the symlink the board's [modem] device names; `shore`: HOST:PORT.
  // `time_scale`: simulated seconds per wall second (the guard times are the
  // firmware's, in simulated seconds).
  ModemBridge(const std::string& link, const std::string& shore_host, int shore_port, double time_scale);
  ~ModemBridge();
  ModemBridge(const ModemBridge&) = delete;
  ModemBridge& operator=(const ModemBridge&) = delete;

  const std::string& link() const { return line_->link(); }
  void append_pollfds(std::vector<pollfd>& fds) const;
  // After ppoll: serves what is readable (fds from append_pollfds), and the guard timer.
  void service(const pollfd* fds, std::size_t count);
  const ModemBridgeStats& stats() const { return stats_; }

 private:
  using Clock = std::chrono::steady_clock;
  void from_glider(const std::uint8_t* data, std::size_t n);
  void from_shore();
  void command(const std::string& line);
  void reply(const std::string& text);
  void to_glider(const std::string& bytes);
  void to_shore(const std::uint8_t* data, std::size_t n);
  void hang_up(bool tell_glider);

  std::unique_ptr<PtyDevice> line_;
  std::string host_;
  int port_;
  Clock::duration guard_;
  int socket_ = -1;
  bool data_mode_ = false;
  bool echo_ = true;
  std::string line_buffer_;
  Clock::time_point last_data_ = Clock::now();
  Clock::time_point escape_at_{};
  bool escape_pending_ = false;
  std::string pending_up_;    // bytes the shore's socket did not take yet
  std::string pending_down_;  // bytes for the glider its line had no room for yet
  ModemBridgeStats stats_;
};

}  // namespace glider::plant
