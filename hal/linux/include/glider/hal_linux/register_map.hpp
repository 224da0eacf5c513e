// SPDX-License-Identifier: Apache-2.0
#pragma once
// The default register map of a position-controlled actuator axis
// (boards/modbus_actuators.md is the documentation of this file). Shared by
// the driver, the actuator simulator and the bench tool, so the three can
// never disagree. Addresses are 0-based offsets from the axis' base address
// (board file: `base_address`); all registers are holding registers.
#include <cstdint>

namespace glider::hal_linux::regs {

enum Offset : int {
  kIdent = 0,        // RO  kIdentValue: "this is a glider actuator axis"
  kVersion = 1,      // RO  map version, major << 8 | minor
  kControl = 2,      // RW  ControlBit
  kTarget = 3,       // RW  target position, int16 counts
  kSpeed = 4,        // RW  speed limit of the move, counts/s (uint16)
  kActual = 5,       // RO  actual position, int16 counts
  kStatus = 6,       // RO  StatusBit
  kFaultCode = 7,    // RO  FaultCode
  kActualSpeed = 8,  // RO  measured speed, int16 counts/s
  kBlockLength = 9,
};

// The driver reads kActual..kActualSpeed in one transaction and writes
// kControl..kSpeed in one transaction (one request per cycle each).
constexpr int kReadBlockStart = kActual;
constexpr int kReadBlockLength = kBlockLength - kActual;
constexpr int kCommandBlockStart = kControl;
constexpr int kCommandBlockLength = kActual - kControl;

constexpr std::uint16_t kIdentValue = 0x4741;  // 'G' 'A'
constexpr std::uint16_t kMapVersion = 0x0100;  // 1.0

enum ControlBit : std::uint16_t {
  kEnable = 1u << 0,      // drive powered; cleared = motor off (coasts)
  kHome = 1u << 1,        // self-clearing: seek the minimum limit switch, zero there
  kStop = 1u << 2,        // hold position, ignore the target
  kClearFault = 1u << 3,  // self-clearing: acknowledge a latched fault
};

enum StatusBit : std::uint16_t {
  kEnabled = 1u << 0,
  kMoving = 1u << 1,
  kInPosition = 1u << 2,  // |actual - target| within one count and not moving
  kHomed = 1u << 3,
  kLimitMin = 1u << 4,  // minimum limit switch closed
  kLimitMax = 1u << 5,  // maximum limit switch closed
  kFault = 1u << 6,     // latched; kFaultCode says why; the axis will not move
};

enum FaultCode : std::uint16_t {
  kNoFault = 0,
  kStall = 1,       // commanded to move, did not move (jammed, motor or drive)
  kOverTravel = 2,  // target beyond the travel: stopped at the limit switch
  kDriveFault = 3,  // drive electronics (over-current, over-temperature)
};

const char* fault_name(std::uint16_t code);

}  // namespace glider::hal_linux::regs
