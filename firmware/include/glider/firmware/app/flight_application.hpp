// SPDX-License-Identifier: Apache-2.0
#pragma once
// The flight application's task table: the flight software (and, first in
// each cycle, the platform's own task where there is one) under the
// Executive. glider-sil and glider-firmware build it the same way; they
// differ only in the HAL they hand it and the clock that drives step().
#include <array>

#include "glider/firmware/executive.hpp"
#include "glider/firmware/flight_software.hpp"

namespace glider::fw::app {

class FlightApplication {
 public:
  // `platform` (may be null) runs before the flight software every cycle
  // (the target: fresh Modbus budgets). Budgets: platform 45 %, flight 50 %
  // of the period, comms (when attached) 5 %.
  FlightApplication(const hal::Hal& hal, const FlightSoftwareConfig& config, PeriodicTask* platform = nullptr,
                    hal::Micros period_us = Executive::kDefaultPeriodUs);
  FlightApplication(const FlightApplication&) = delete;
  FlightApplication& operator=(const FlightApplication&) = delete;

  bool valid() const { return executive_.valid(); }
  Executive& executive() { return executive_; }
  const Executive& executive() const { return executive_; }
  FlightSoftware& flight() { return flight_; }
  const FlightSoftware& flight() const { return flight_; }
  // The comms task (surface dialog, modem; firmware/src/comms) runs after
  // the flight software every cycle once attached (it needs flight() first).
  void attach_comms(PeriodicTask& comms) { comms_slot_.task = &comms; }

 private:
  // Runs the attached comms task, if any.
  struct CommsSlot final : PeriodicTask {
    PeriodicTask* task = nullptr;
    void run(hal::Micros now_us) override {
      if (task != nullptr) task->run(now_us);
    }
  };
  FlightSoftware flight_;
  CommsSlot comms_slot_;
  std::array<TaskSlot, 3> tasks_;
  Executive executive_;
};

}  // namespace glider::fw::app
