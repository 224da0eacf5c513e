// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/app/flight_application.hpp"

#include <span>

namespace glider::fw::app {

FlightApplication::FlightApplication(const hal::Hal& hal, const FlightSoftwareConfig& config, PeriodicTask* platform,
                                     hal::Micros period_us)
    : flight_(hal, config),
      tasks_{{{"platform", platform, 1, period_us * 45 / 100},
              {"flight", &flight_, 1, period_us / 2},
              {"comms", &comms_slot_, 1, period_us / 20}}},
      executive_(hal.clock,
                 platform != nullptr ? std::span<const TaskSlot>(tasks_) : std::span<const TaskSlot>(&tasks_[1], 2),
                 period_us) {
  flight_.attach_executive(&executive_);
}

}  // namespace glider::fw::app
