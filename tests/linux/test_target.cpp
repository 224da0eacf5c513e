// SPDX-License-Identifier: Apache-2.0
// The target's loop statistics and its board file.
#include <CppUTest/TestHarness.h>

#include <string>

#include "../unit/config_error.hpp"
#include "glider/target/loop_timing.hpp"
#include "glider/target/target_board.hpp"

using namespace glider;

TEST_GROUP(LoopTiming){};

TEST(LoopTiming, LatenessHistogramAndOverruns) {
  target::LoopTiming timing;
  for (int i = 0; i < 98; ++i) timing.record(100, 500, 1'000'000);  // 100 us late: bucket < 128
  timing.record(5'000, 500, 1'000'000);
  timing.record(999'800, 500, 1'000'000);  // late + work past the period: an overrun
  CHECK_EQUAL(100u, timing.cycles());
  CHECK_EQUAL(1u, timing.overruns());
  CHECK_EQUAL(127, timing.lateness_quantile_us(0.5));
  CHECK_EQUAL(8191, timing.lateness_quantile_us(0.99));
  CHECK_EQUAL(999'800, timing.max_lateness_us());
  DOUBLES_EQUAL((98 * 100 + 5'000 + 999'800) / 100.0, timing.mean_lateness_us(), 1e-9);
  char line[256];
  timing.format(line, sizeof line);
  STRCMP_CONTAINS("cycles 100, wake-up late mean 10146 us, p50 <= 127 us, p99 <= 8191 us, max 999800 us", line);
}

namespace {

const std::string kBoard = R"(name = "t"
[actuators]
board = "boards/actuators/default_modbus.toml"
[gps]
device = "/dev/ttyS1"
[compass]
device = "/dev/ttyS2"
baud = 19200
[depth]
device = "/dev/ttyS3"
)";

std::string error_of(const std::string& text) {
  return test::config_error_of([&] { target::parse_target_board(text, "board.toml", GLIDER_SOURCE_DIR); });
}

}  // namespace

TEST_GROUP(TargetBoardFile){};

TEST(TargetBoardFile, TheShippedBoardReads) {
  const auto board = target::load_target_board(GLIDER_SOURCE_DIR "/boards/target/cm4_glider.toml");
  CHECK_TRUE(board.loop.sched_fifo && board.loop.lock_memory);
  CHECK_TRUE(board.gpio_board.has_value());
  STRCMP_EQUAL("/dev/ttyAMA3", board.depth.bus.device.c_str());
  CHECK_EQUAL(3'000'000, board.compass.stale_after_us);
  STRCMP_EQUAL("", error_of(kBoard).c_str());
}

TEST(TargetBoardFile, ProblemsNameFileLineAndKey) {
  STRCMP_CONTAINS("board.toml:3:9: actuators.board: no such file",
                  error_of(test::replaced(kBoard, "default_modbus", "nope")).c_str());
  STRCMP_CONTAINS("board.toml:8:8: compass.baud: not a standard baud rate",
                  error_of(test::replaced(kBoard, "19200", "19201")).c_str());
  STRCMP_CONTAINS("board.toml: missing required key 'depth.device'",
                  error_of(test::replaced(kBoard, "device = \"/dev/ttyS3\"", "")).c_str());
  STRCMP_CONTAINS(
      "board.toml:11:10: unknown key 'depth.devise'",
      error_of(test::replaced(kBoard, "device = \"/dev/ttyS3\"", "device = \"x\"\ndevise = \"y\"")).c_str());
  STRCMP_CONTAINS("depth.water_density_kg_m3: value 1.025 is outside the allowed range [990, 1050] kg/m^3",
                  error_of(kBoard + "water_density_kg_m3 = 1.025\n").c_str());
}
