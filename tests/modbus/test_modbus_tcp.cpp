// SPDX-License-Identifier: Apache-2.0
// The driver against the actuator simulator over Modbus TCP on loopback
// (an ephemeral port per test), fault by fault.
#include <CppUTest/TestHarness.h>

#include "child_process.hpp"
#include "glider/hal_linux/register_map.hpp"
#include "modbus_fixture.hpp"

using namespace glider;
using glider::test::DriverUnderTest;
using glider::test::Simulator;
namespace regs = hal_linux::regs;

namespace {

std::string loopback(int port) { return "127.0.0.1:" + std::to_string(port); }

// A port nobody listens on: bind an ephemeral one, then let it go.
int closed_port() {
  Simulator sim({"--tcp", "127.0.0.1:0"});
  const int port = sim.tcp_port();
  sim.stop();
  return port;
}

}  // namespace

TEST_GROUP(ModbusTcp){};

TEST(ModbusTcp, IdentifiesMovesAndReadsBackInEngineeringUnits) {
  Simulator sim({"--tcp", "127.0.0.1:0"});
  DriverUnderTest d("--tcp", loopback(sim.tcp_port()));
  const hal_linux::AxisIdentity id = d.pump->identify();
  CHECK(id.answered);
  CHECK(id.recognised);
  CHECK(d.pump->command(-120.5));
  CHECK(d.slide->command(0.25));
  CHECK(test::settles_at(d, *d.pump, -120.5));
  CHECK(test::settles_at(d, *d.slide, 0.25));
  const hal_linux::AxisStatus s = test::status_with(d, *d.slide, regs::kInPosition);
  CHECK(s.has(regs::kInPosition));
  CHECK(s.has(regs::kEnabled));
  CHECK_FALSE(s.has(regs::kFault));
}

TEST(ModbusTcp, RefusesATargetOutsideTheLimitsAndReportsIt) {
  Simulator sim({"--tcp", "127.0.0.1:0"});
  DriverUnderTest d("--tcp", loopback(sim.tcp_port()));
  CHECK_FALSE(d.pump->command(260.0));  // max_cc = 250
  const hal::ActuatorReading r = d.cycle_read(*d.pump);
  CHECK(r.valid);
  CHECK(r.fault);
  DOUBLES_EQUAL(0.0, r.position, 1e-9);  // nothing was sent: it did not move
  CHECK(d.pump->command(250.0));
  CHECK(test::settles_at(d, *d.pump, 250.0));
}

TEST(ModbusTcp, HomingSeeksTheMinimumLimitSwitch) {
  Simulator sim({"--tcp", "127.0.0.1:0"});
  DriverUnderTest d("--tcp", loopback(sim.tcp_port()));
  CHECK(d.slide->home());
  CHECK(test::settles_at(d, *d.slide, d.board.slide.travel_min));
  const hal_linux::AxisStatus s = d.slide->read_status();
  CHECK(s.has(regs::kHomed));
  CHECK(s.has(regs::kLimitMin));
}

TEST(ModbusTcp, OccasionalGarbledRepliesAreRetried) {
  Simulator sim({"--tcp", "127.0.0.1:0", "--fault", "noise:2"});
  DriverUnderTest d("--tcp", loopback(sim.tcp_port()));
  for (int i = 0; i < 6; ++i) {
    const hal::ActuatorReading r = d.cycle_read(*d.pump);
    CHECK(r.valid);
    CHECK_FALSE(r.fault);
  }
  CHECK(d.link->stats().attempts > d.link->stats().transactions);
  CHECK_EQUAL(0u, d.link->stats().failed);
}

TEST(ModbusTcp, GarbledRepliesEveryTimeAreAFaultNotAValue) {
  Simulator sim({"--tcp", "127.0.0.1:0", "--fault", "noise:1"});
  DriverUnderTest d("--tcp", loopback(sim.tcp_port()));
  const hal::ActuatorReading r = d.cycle_read(*d.pump);
  CHECK_FALSE(r.valid);
  CHECK(r.fault);
  CHECK_EQUAL(1u + static_cast<unsigned>(d.board.bus.retries), d.link->stats().attempts);
}

TEST(ModbusTcp, ExceptionRepliesAreRetriedThenAFault) {
  Simulator sim({"--tcp", "127.0.0.1:0", "--fault", "exception:1"});
  DriverUnderTest d("--tcp", loopback(sim.tcp_port()));
  const hal::ActuatorReading r = d.cycle_read(*d.pump);
  CHECK(r.fault);
  STRCMP_EQUAL("Slave device or server failure", d.link->last_error());
}

TEST(ModbusTcp, AnOccasionalExceptionIsRetried) {
  Simulator sim({"--tcp", "127.0.0.1:0", "--fault", "exception:3"});
  DriverUnderTest d("--tcp", loopback(sim.tcp_port()));
  for (int i = 0; i < 6; ++i) CHECK_FALSE(d.cycle_read(*d.slide).fault);
}

TEST(ModbusTcp, RepliesLaterThanTheTimeoutAreAFaultAndNeverTakenForTheNextAnswer) {
  Simulator sim({"--tcp", "127.0.0.1:0", "--fault", "slow:150"});  // response timeout 100 ms
  DriverUnderTest d("--tcp", loopback(sim.tcp_port()));
  CHECK(d.cycle_read(*d.pump).fault);
  CHECK(d.cycle_read(*d.slide).fault);  // the late pump replies must not pass for the slide
  CHECK(d.link->stats().failed >= 2u);
}

TEST(ModbusTcp, ADeviceThatStopsAnsweringMidMoveIsAFault) {
  Simulator sim({"--tcp", "127.0.0.1:0", "--fault", "silent:4"});
  DriverUnderTest d("--tcp", loopback(sim.tcp_port()));
  CHECK(d.pump->command(200.0));             // request 1
  CHECK_FALSE(d.cycle_read(*d.pump).fault);  // 2
  CHECK_FALSE(d.cycle_read(*d.pump).fault);  // 3
  CHECK_FALSE(d.cycle_read(*d.pump).fault);  // 4
  const hal::ActuatorReading r = d.cycle_read(*d.pump);
  CHECK_FALSE(r.valid);
  CHECK(r.fault);
  STRCMP_EQUAL("Connection timed out", d.link->last_error());
}

TEST(ModbusTcp, AStalledActuatorReportsItsFault) {
  Simulator sim({"--tcp", "127.0.0.1:0", "--fault", "stall:1"});  // after 1 simulated s of motion
  DriverUnderTest d("--tcp", loopback(sim.tcp_port()));
  CHECK(d.pump->command(200.0));
  hal::ActuatorReading r;
  for (int i = 0; i < 100 && !r.fault; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    r = d.cycle_read(*d.pump);
  }
  CHECK(r.valid);  // it answers: the position is real, and stuck short of the target
  CHECK(r.fault);
  CHECK(r.position < 200.0);
  CHECK_EQUAL(regs::kStall, d.pump->read_status().fault_code);
  CHECK(d.pump->clear_fault());
  CHECK(d.pump->command(200.0));
  CHECK(test::settles_at(d, *d.pump, 200.0));
}

TEST(ModbusTcp, NobodyListeningIsAFault) {
  DriverUnderTest d("--tcp", loopback(closed_port()));
  CHECK_FALSE(d.link->connected());
  CHECK_FALSE(d.pump->command(10.0));
  const hal::ActuatorReading r = d.cycle_read(*d.pump);
  CHECK(r.fault);
  CHECK(d.pump->command_pending());
}

TEST(ModbusTcp, ALostConnectionIsAFaultAndTheLinkComesBackWithTheDevice) {
  auto sim = std::make_unique<Simulator>(std::vector<std::string>{"--tcp", "127.0.0.1:0"});
  const int port = sim->tcp_port();
  DriverUnderTest d("--tcp", loopback(port));
  CHECK_FALSE(d.cycle_read(*d.pump).fault);
  sim.reset();  // the device goes away (cable, power)
  CHECK(d.cycle_read(*d.pump).fault);
  sim = std::make_unique<Simulator>(std::vector<std::string>{"--tcp", loopback(port)});
  CHECK_FALSE(d.cycle_read(*d.pump).fault);
  CHECK(d.link->stats().reconnects >= 2u);
}

TEST(ModbusTcp, UnknownRegistersAndReadOnlyWritesAreRefusedByTheDevice) {
  Simulator sim({"--tcp", "127.0.0.1:0"});
  DriverUnderTest d("--tcp", loopback(sim.tcp_port()));
  std::uint16_t value = 5;
  CHECK_FALSE(d.link->write_registers(1, regs::kActual, 1, &value));
  STRCMP_EQUAL("Illegal data address", d.link->last_error());
  CHECK_EQUAL(1u, d.link->stats().attempts);  // a permanent refusal is not retried
}
