// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/register_map.hpp"

namespace glider::hal_linux::regs {

const char* fault_name(std::uint16_t code) {
  switch (code) {
    case kNoFault:
      return "none";
    case kStall:
      return "stall";
    case kOverTravel:
      return "over-travel";
    case kDriveFault:
      return "drive fault";
    default:
      return "unknown fault code";
  }
}

}  // namespace glider::hal_linux::regs
