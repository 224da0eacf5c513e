// SPDX-License-Identifier: Apache-2.0
#pragma once
// The driver side of the Modbus tests: the default board's link and axes,
// pointed at a real peer.
#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "glider/hal_linux/modbus_axis.hpp"
#include "glider/hal_linux/modbus_board.hpp"
#include "glider/hal_linux/modbus_link.hpp"

namespace glider::test {

struct DriverUnderTest {
  hal_linux::ModbusBoard board;
  std::string warning;
  std::unique_ptr<hal_linux::ModbusLink> link;
  std::unique_ptr<hal_linux::ModbusAxis> pump;
  std::unique_ptr<hal_linux::ModbusAxis> slide;

  // "--tcp"/"--rtu" as the tools take them; serial_mode rs485 on RTU, which
  // a pty refuses (the driver must carry on).
  DriverUnderTest(const std::string& transport, const std::string& where) {
    board = hal_linux::load_modbus_board(GLIDER_SOURCE_DIR "/boards/actuators/default_modbus.toml");
    if (transport == "--tcp") {
      hal_linux::use_tcp_endpoint(board.bus, where);
    } else {
      hal_linux::use_rtu_device(board.bus, where);
      board.bus.rs485 = true;
    }
    std::string error;
    link = hal_linux::ModbusLink::open(board.bus, warning, error);
    if (!link) throw std::runtime_error(error);
    pump = std::make_unique<hal_linux::ModbusAxis>(*link, board.pump);
    slide = std::make_unique<hal_linux::ModbusAxis>(*link, board.slide);
  }
  // The next control cycle (a fresh blocking budget).
  hal::ActuatorReading cycle_read(hal_linux::ModbusAxis& axis) {
    link->begin_cycle();
    return axis.read(0);
  }
};

// Polls (one read per simulated control cycle) until the axis reports
// `position` (one count) or `cycles` cycles have passed. Not a timing test:
// the simulator runs 20x faster than real time.
inline bool settles_at(DriverUnderTest& d, hal_linux::ModbusAxis& axis, double position, int cycles = 200) {
  for (int i = 0; i < cycles; ++i) {
    const hal::ActuatorReading r = d.cycle_read(axis);
    if (r.valid && !r.fault && std::abs(r.position - position) <= 1.0 / axis.config().counts_per_unit) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// The axis's status once it reports `bit`, polled as settles_at (the last
// status read if it never does). The simulator sets "in position" one of its
// own steps after the position arrives (the arriving step still moved), so
// a status read right after settles_at may still say "moving": under load
// the simulator's step can lag the driver's poll (a fresh-clone run at load
// 7 read it so once).
inline hal_linux::AxisStatus status_with(DriverUnderTest& d, hal_linux::ModbusAxis& axis, std::uint16_t bit,
                                         int cycles = 200) {
  hal_linux::AxisStatus s;
  for (int i = 0; i < cycles; ++i) {
    d.link->begin_cycle();
    s = axis.read_status();
    if (s.has(bit)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return s;
}

}  // namespace glider::test
