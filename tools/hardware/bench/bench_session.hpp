// SPDX-License-Identifier: Apache-2.0
#pragma once
// A bench session: one bus, the board's two axes, moves watched with
// progress on stderr and every sample logged to an optional CSV file.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "glider/hal_linux/modbus_axis.hpp"
#include "glider/hal_linux/modbus_board.hpp"
#include "glider/hal_linux/modbus_link.hpp"
#include "move_metrics.hpp"

namespace glider::bench {

struct MoveOutcome {
  bool arrived = false;
  std::string problem;  // why not: fault, no answer, took too long
  std::vector<Sample> samples;
};

class BenchSession {
 public:
  // Throws std::runtime_error when the bus cannot be opened at all.
  BenchSession(const hal_linux::ModbusBoard& board, const std::string& csv_path);
  ~BenchSession();

  hal_linux::ModbusAxis& axis(const std::string& name);
  const hal_linux::ModbusBoard& board() const { return board_; }
  hal_linux::ModbusLink& link() { return *link_; }
  const std::string& warning() const { return warning_; }

  hal_linux::AxisStatus poll(hal_linux::ModbusAxis& axis);
  // Commands the move (target, or homing when `home`) and watches it until
  // the axis is in position, reports a fault, stops answering or overruns
  // twice its expected time.
  MoveOutcome move(hal_linux::ModbusAxis& axis, double target, double rate, bool home = false);

  // How the session ended, for the CSV's trailer (docs/flight-log.md): "complete"
  // or "stopped <reason>"; a session that never says is "stopped error".
  void finish(std::string outcome) { outcome_ = std::move(outcome); }

 private:
  hal_linux::ModbusBoard board_;
  std::string warning_;
  std::unique_ptr<hal_linux::ModbusLink> link_;
  std::unique_ptr<hal_linux::ModbusAxis> pump_;
  std::unique_ptr<hal_linux::ModbusAxis> slide_;
  bool write_whole(const char* data, std::size_t size);

  int csv_ = -1;  // the --csv file: whole rows with write(2), a trailer at the end
  std::uint64_t csv_bytes_ = 0;
  std::uint64_t csv_rows_ = 0;
  std::uint64_t csv_lost_ = 0;
  std::string outcome_ = "stopped error";
};

std::string describe_status(const hal_linux::AxisStatus& status, const std::string& unit);

}  // namespace glider::bench
