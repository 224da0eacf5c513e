#include <CppUTest/TestHarness.h>

#include <cmath>
#include <limits>

#include "glider/firmware/flight_software.hpp"

using namespace glider;
using hal::Micros;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A scripted HAL: tests set what the sensors say and read what was commanded.
struct FakeHal final : hal::Clock, hal::DepthSensor, hal::BuoyancyPump, hal::BatterySlide, hal::LogSink {
  struct Attitude final : hal::AttitudeSensor {
    hal::AttitudeSample sample{};
    hal::AttitudeSample read() override { return sample; }
  } attitude;

  Micros now = 0;
  hal::DepthSample depth{};
  double pump_cc = 250.0;
  double battery_in = 0.0;
  bool pump_fault = false;
  double commanded_cc = kNaN;
  double commanded_in = kNaN;
  int pump_commands = 0;
  bool accept_log = true;
  hal::FlightLogRecord last_row{};
  int rows = 0;

  Micros now_us() const override { return now; }
  hal::DepthSample read() override { return depth; }
  void command_volume_cc(double cc) override {
    commanded_cc = cc;
    ++pump_commands;
  }
  hal::ActuatorReading read_volume_cc() override { return {pump_cc, now, true, pump_fault}; }
  void command_position_in(double in) override { commanded_in = in; }
  hal::ActuatorReading read_position_in() override { return {battery_in, now, true, false}; }
  bool write(const hal::FlightLogRecord& row) override {
    last_row = row;
    ++rows;
    return accept_log;
  }

  void sense(double depth_m, double pitch_rad) {
    depth = {depth_m, now, true};
    attitude.sample = {pitch_rad, 0.0, 1.0, now, true};
  }
  hal::Hal hal() { return {*this, *this, attitude, *this, *this, *this}; }
};

}  // namespace

TEST_GROUP(FlightSoftware) {
  FakeHal fake;
  fw::FlightSoftwareConfig config;

  void cycle(fw::FlightSoftware & flight) {
    flight.run(fake.now);
    fake.now += 1'000'000;
  }
};

TEST(FlightSoftware, StartsTheDiveAndLogsARow) {
  fw::FlightSoftware flight(fake.hal(), config);
  fake.sense(0.2, 0.1);
  cycle(flight);
  CHECK(flight.phase() == fw::Phase::kDive);
  DOUBLES_EQUAL(config.mission.dive_ballast_cc, fake.commanded_cc, 0.0);
  DOUBLES_EQUAL(config.dive_battpos_in, fake.commanded_in, 0.0);
  LONGS_EQUAL(1, fake.rows);
  DOUBLES_EQUAL(0.2, fake.last_row.m_depth, 0.0);
  LONGS_EQUAL(1, fake.last_row.m_depth_state);
  CHECK_TRUE(std::isnan(fake.last_row.m_depth_rate));  // needs two samples
}

TEST(FlightSoftware, HoldsTheBatteryUntilThePumpArrives) {
  fw::FlightSoftware flight(fake.hal(), config);
  fake.sense(0.2, 0.0);
  cycle(flight);
  // Pump still far from -250 cc, pitch far from target: battery held.
  fake.pump_cc = 0.0;
  fake.sense(0.5, 0.3);
  cycle(flight);
  DOUBLES_EQUAL(config.dive_battpos_in, fake.commanded_in, 0.0);
  // Pump there: the servo acts (nose too high -> battery forward).
  fake.pump_cc = config.mission.dive_ballast_cc;
  fake.sense(1.0, 0.0);
  cycle(flight);
  CHECK(fake.commanded_in > config.dive_battpos_in);
}

TEST(FlightSoftware, CommandsThePumpOnlyWhenTheSetpointChanges) {
  fw::FlightSoftware flight(fake.hal(), config);
  for (int i = 0; i < 5; ++i) {
    fake.sense(1.0 + i, -0.4);
    cycle(flight);
  }
  LONGS_EQUAL(1, fake.pump_commands);
}

TEST(FlightSoftware, StaleDepthAbortsAfterTheTimeoutNotBefore) {
  fw::FlightSoftware flight(fake.hal(), config);
  fake.sense(10.0, -0.4);
  cycle(flight);
  const Micros last_good = fake.depth.time_us;
  fake.depth.valid = false;
  while (fake.now - last_good <= static_cast<Micros>(config.sensor_timeout_s * 1e6)) {
    fake.attitude.sample.time_us = fake.now;
    cycle(flight);
    CHECK(flight.phase() == fw::Phase::kDive);
    CHECK_TRUE(std::isnan(fake.last_row.m_depth));  // never a made-up value
  }
  fake.attitude.sample.time_us = fake.now;
  cycle(flight);
  CHECK(flight.phase() == fw::Phase::kAbort);
  CHECK(flight.abort_cause() == fw::AbortCause::kDepthSensor);
  // The abort sequence: full buoyancy, battery full aft.
  DOUBLES_EQUAL(config.limits.ballast_max_cc, fake.commanded_cc, 0.0);
  DOUBLES_EQUAL(config.limits.battery_min_in, fake.commanded_in, 0.0);
  LONGS_EQUAL(static_cast<long>(fw::AbortCause::kDepthSensor), fake.last_row.x_abort_cause);
}

TEST(FlightSoftware, NonFinitePitchIsInvalid) {
  config.sensor_timeout_s = 2.0;
  fw::FlightSoftware flight(fake.hal(), config);
  fake.sense(5.0, -0.4);
  cycle(flight);
  for (int i = 0; i < 4; ++i) {
    fake.sense(5.0 + i, kNaN);
    cycle(flight);
  }
  CHECK(flight.phase() == fw::Phase::kAbort);
  CHECK(flight.abort_cause() == fw::AbortCause::kAttitudeSensor);
}

TEST(FlightSoftware, ActuatorFaultAborts) {
  fw::FlightSoftware flight(fake.hal(), config);
  fake.sense(5.0, -0.4);
  cycle(flight);
  fake.pump_fault = true;
  fake.sense(6.0, -0.4);
  cycle(flight);
  CHECK(flight.abort_cause() == fw::AbortCause::kActuatorFault);
  CHECK_TRUE(std::isnan(fake.last_row.m_ballast_pumped));
}

TEST(FlightSoftware, LostLogRowsAreCounted) {
  fw::FlightSoftware flight(fake.hal(), config);
  fake.accept_log = false;
  fake.sense(1.0, 0.0);
  cycle(flight);
  cycle(flight);
  LONGS_EQUAL(2, flight.log_rows_lost());
}

TEST(FlightSoftware, DepthRateIsFilteredFromDepth) {
  fw::FlightSoftware flight(fake.hal(), config);
  for (int i = 0; i < 60; ++i) {  // steady 0.2 m/s descent
    fake.pump_cc = config.mission.dive_ballast_cc;
    fake.sense(1.0 + 0.2 * i, config.mission.dive_pitch_rad);
    cycle(flight);
  }
  DOUBLES_EQUAL(0.2, fake.last_row.m_depth_rate, 1e-9);
}

TEST(FlightSoftware, ValidationNamesTheProblem) {
  STRCMP_EQUAL("", fw::validate(config));
  config.limits.battery_min_in = 2.0;
  STRCMP_EQUAL("battery_min_in must be below battery_max_in", fw::validate(config));
}
