// SPDX-License-Identifier: Apache-2.0
// glider-firmware's path to the Slocum files: the loop hands rows to the
// ring log, whose writer thread formats the CSV and feeds the Slocum writer
// with the same UTC time. The .dbd read back equals the CSV log the thread
// wrote, value for value, UTC times included.
#include <CppUTest/TestHarness.h>

#include <bit>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "glider/firmware/log/slocum_directory_sink.hpp"
#include "glider/firmware/log/slocum_writer.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/slocum/deployment.hpp"
#include "glider/target/loop_clock.hpp"
#include "glider/target/ring_log.hpp"

using namespace glider;
namespace fs = std::filesystem;

TEST_GROUP(SlocumWriterTarget){};

TEST(SlocumWriterTarget, RingLogThreadWritesTheCsvsValues) {
  const fs::path dir = fs::path(GLIDER_TEST_OUTPUT_DIR) / "slocum_writer" / "target";
  fs::remove_all(dir);
  fs::create_directories(dir);
  fw::SlocumDirectorySink sink((dir / "slocum").string());
  fw::SlocumLogOptions options;
  options.vehicle = "bench";
  fw::SlocumLogger slocum(sink, options);
  CHECK_TRUE(slocum.start());
  // Rows stamped as the target stamps them: the loop clock told in UTC (here
  // the loop clock runs 1000 times faster: rows 250 ms of loop time apart are
  // handed over about 250 us apart).
  const target::LoopClock clock(1000.0);
  target::RingLogOptions log_options;
  log_options.loop_clock = &clock;
  log_options.slocum = &slocum;
  const int rows = 900;
  {
    target::RingBufferLog log((dir / "flight.csv").string(), log_options);
    for (int i = 0; i < rows; ++i) {
      hal::FlightLogRecord r;
      r.time_us = static_cast<hal::Micros>(i) * 250'000;
      r.m_depth = 0.1 * (i % 300) + 1e-3 * std::sin(i);
      r.m_pitch = i % 3 == 0 ? std::nan("") : -0.4 + 1e-4 * i;
      r.m_depth_state = i % 300 < 20 ? 0 : 1;
      r.m_lat = 4330.12345678 + 1e-7 * i;
      r.x_yo_count = i / 100;
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
      while (!log.write(r) && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
    }
    CHECK_TRUE(log.close("complete"));
  }
  CHECK_TRUE(slocum.finish());
  CHECK_EQUAL(3, slocum.segments());

  const flightlog::FlightLog csv = flightlog::read_flight_log(dir / "flight.csv");
  std::vector<std::string> inputs;
  for (const auto& entry : fs::directory_iterator(dir / "slocum")) {
    if (entry.path().extension() == ".dbd") inputs.push_back(entry.path().string());
  }
  const slocum::Deployment read = slocum::read_deployment(slocum::deployment_files(inputs));
  CHECK_EQUAL(static_cast<std::size_t>(rows), csv.rows());
  CHECK_EQUAL(csv.rows(), read.log.rows());
  // UTC times (the ring log's stamp), bit for bit.
  CHECK(csv.time().front() > 1.6e9);
  // The loop clock told in UTC (docs/comms.md, the Slocum files' time base):
  // rows 250 ms of loop time apart are 250 ms apart in the files, though the
  // loop clock ran 1000 times faster than the wall clock (old: 250 us apart).
  for (std::size_t i = 1; i < csv.rows(); ++i) CHECK(std::fabs(csv.time()[i] - csv.time()[i - 1] - 0.25) < 1e-5);
  for (std::size_t i = 0; i < csv.rows(); ++i) {
    CHECK_EQUAL(std::bit_cast<std::uint64_t>(csv.time()[i]), std::bit_cast<std::uint64_t>(read.log.time()[i]));
  }
  for (const char* name : {"m_depth", "m_pitch", "m_lat", "x_yo_count", "m_depth_state"}) {
    const auto& want = csv.column(name);
    const auto& got = read.log.column(name);
    const int bytes = fw::kSlocumFlightSensors[*fw::slocum_flight_sensor(name)].bytes;
    for (std::size_t i = 0; i < csv.rows(); ++i) {
      const double expected =
          bytes == 4 && !std::isnan(want[i]) ? static_cast<double>(static_cast<float>(want[i])) : want[i];
      CHECK_TRUE((std::isnan(expected) && std::isnan(got[i])) ||
                 std::bit_cast<std::uint64_t>(expected) == std::bit_cast<std::uint64_t>(got[i]));
    }
  }
}
