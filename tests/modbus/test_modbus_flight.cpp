// SPDX-License-Identifier: Apache-2.0
// The flight software on the Modbus pump and slide: a device that stops
// answering mid-dive ends in the actuator-fault abort.
#include <CppUTest/TestHarness.h>

#include "../unit/fake_hal.hpp"
#include "child_process.hpp"
#include "glider/firmware/flight_software.hpp"
#include "glider/hal_linux/modbus_actuators.hpp"
#include "modbus_fixture.hpp"

using namespace glider;

TEST_GROUP(ModbusFlight){};

TEST(ModbusFlight, ADeadActuatorBusAbortsTheMission) {
  test::Simulator sim({"--tcp", "127.0.0.1:0", "--fault", "silent:12"});
  test::DriverUnderTest d("--tcp", "127.0.0.1:" + std::to_string(sim.tcp_port()));
  test::FakeHal fake;  // clock and sensors; actuators are Modbus
  hal_linux::ModbusBuoyancyPump pump(*d.pump, fake);
  hal_linux::ModbusBatterySlide slide(*d.slide, fake);
  const hal::Hal hal = fake.with_actuators(pump, slide);
  fw::FlightSoftwareConfig config;
  fw::FlightSoftware flight(hal, config);
  int cycles = 0;
  for (; cycles < 20 && flight.phase() != fw::Phase::kAbort; ++cycles) {
    fake.sense(10.0, -0.4);
    d.link->begin_cycle();
    flight.run(fake.now);
    fake.now += hal::kMicrosPerSecond;
  }
  CHECK(flight.phase() == fw::Phase::kAbort);
  CHECK(flight.abort_cause() == fw::AbortCause::kActuatorFault);
  CHECK(cycles > 2);  // it flew on the Modbus actuators until they went silent
}
