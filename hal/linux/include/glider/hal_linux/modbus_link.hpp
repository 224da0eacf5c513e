// SPDX-License-Identifier: Apache-2.0
#pragma once
// One Modbus bus (RTU serial line or TCP connection) shared by the actuator
// axes on it, with the flight loop's timing guarantees: every transaction is
// bounded (short libmodbus timeouts, bounded retries), and all the
// transactions of one control period together block at most the board's
// cycle budget; past it they fail at once. Failures are returned and
// remembered (last_error()), never thrown: the loop path does not throw.
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "glider/hal_linux/modbus_board.hpp"

struct _modbus;  // NOLINT(bugprone-reserved-identifier): libmodbus' own name for modbus_t

namespace glider::hal_linux {

struct LinkStats {
  std::uint64_t transactions = 0;  // requested by the axes
  std::uint64_t failed = 0;        // gave up after the retries or the budget
  std::uint64_t attempts = 0;      // requests put on the bus
  std::uint64_t budget_refusals = 0;
  std::uint64_t reconnects = 0;
};

class ModbusLink {
 public:
  using Clock = std::chrono::steady_clock;

  // Start-up: creates the libmodbus context and tries to connect once. A
  // link that could not connect still works: it reconnects on later
  // transactions (within the budget). `warning` gets non-fatal problems
  // (RS-485 mode refused by a pty); empty on success. Returns null and sets
  // `error` only when the configuration itself is unusable.
  static std::unique_ptr<ModbusLink> open(const BusConfig& bus, std::string& warning, std::string& error);
  ~ModbusLink();
  ModbusLink(const ModbusLink&) = delete;
  ModbusLink& operator=(const ModbusLink&) = delete;

  bool read_registers(int slave, int address, int count, std::uint16_t* out) noexcept;
  bool write_registers(int slave, int address, int count, const std::uint16_t* values) noexcept;

  // Starts a new budget window now (the platform may call it at the start
  // of each control cycle; otherwise a window starts at the first
  // transaction a cycle_period after the previous window began).
  void begin_cycle() noexcept;

  bool connected() const { return connected_; }
  // libmodbus' or the link's reason for the last failure (static string).
  const char* last_error() const { return last_error_; }
  const LinkStats& stats() const { return stats_; }
  const BusConfig& bus() const { return bus_; }

 private:
  ModbusLink(const BusConfig& bus, _modbus* context);
  template <typename Request>
  bool transact(int slave, Request&& request) noexcept;
  bool connect() noexcept;
  void disconnect() noexcept;
  void drain_late_reply() noexcept;
  bool fits_budget(Clock::time_point now) const noexcept;

  BusConfig bus_;
  _modbus* context_;
  bool connected_ = false;
  bool needs_flush_ = false;
  bool serial_mode_refused_ = false;
  int serial_mode_errno_ = 0;
  const char* last_error_ = "";
  LinkStats stats_;
  Clock::duration attempt_cost_;
  Clock::time_point window_start_{};
  Clock::time_point window_deadline_{};
  bool window_open_ = false;
};

}  // namespace glider::hal_linux
