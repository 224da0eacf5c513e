// SPDX-License-Identifier: Apache-2.0
// The target's flight log: rows handed over by the loop come out in the
// CSV file, in order, with the docs/flight-log.md columns; a value the
// firmware did not have (NaN) is an empty field.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "glider/target/ring_log.hpp"

using namespace glider;

TEST_GROUP(RingBufferLog){};

TEST(RingBufferLog, RowsReachTheFileInOrder) {
  const std::string path = GLIDER_TEST_OUTPUT_DIR "/ring_log.csv";
  target::RingBufferLog log(path);
  for (int i = 0; i < 3000; ++i) {  // more than the ring holds: the writer thread drains while we write
    hal::FlightLogRecord r;
    r.time_us = static_cast<hal::Micros>(i) * 1'000'000;
    r.m_depth = i % 2 == 0 ? 0.25 * i : std::nan("");
    r.m_depth_state = 1;
    r.x_yo_count = i;
    while (!log.write(r)) {
    }  // a full ring refuses (counted); the loop would drop the row, the test retries
  }
  CHECK_TRUE(log.close());
  CHECK_EQUAL(3000u, log.rows_written());
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (line[0] != '#') lines.push_back(line);
  }
  CHECK_EQUAL(3001u, lines.size());
  STRCMP_EQUAL(
      "m_present_time,m_depth,m_depth_rate,m_pitch,m_roll,m_heading,m_ballast_pumped,c_ballast_pumped,"
      "m_battpos,c_battpos,c_pitch,m_depth_state,x_yo_count,x_abort_cause,x_loop_overruns",
      lines[0].c_str());
  STRCMP_EQUAL("2.000000,0.5,0,0,0,0,0,0,0,0,0,1,2,0,0", lines[3].c_str());
  STRCMP_EQUAL("2999.000000,,0,0,0,0,0,0,0,0,0,1,2999,0,0", lines[3000].c_str());
}
