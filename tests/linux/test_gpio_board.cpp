// SPDX-License-Identifier: Apache-2.0
// GPIO board files: the shipped ones read, malformed ones are refused at
// start-up with file, line and problem. (The lines themselves are tested on
// a real kernel: tests/gpio_kernel.)
#include <CppUTest/TestHarness.h>

#include <string>

#include "../unit/config_error.hpp"
#include "glider/config/toml_document.hpp"
#include "glider/hal_linux/gpio_board.hpp"

using namespace glider;
using hal_linux::LineRole;

namespace {

const char* const kValid = R"(name = "test"
[lines.leak]
chip = "gpiochip0"
line = "LEAK"
active_low = true
bias = "pull-up"
latch = true
[lines.drop_weight]
chip = "gpiochip0"
line = "BURN"
)";

std::string error_of(const std::string& text) {
  return test::config_error_of([&] { hal_linux::parse_gpio_board(text, "gpio.toml"); });
}

using test::replaced;

}  // namespace

TEST_GROUP(GpioBoardFile){};

TEST(GpioBoardFile, TheShippedBoardsRead) {
  const auto board = hal_linux::load_gpio_board(GLIDER_SOURCE_DIR "/boards/gpio/cm4_glider.toml");
  CHECK_EQUAL(6u, board.lines.size());
  const hal_linux::LineConfig* leak = board.find(LineRole::kLeak);
  CHECK(leak != nullptr);
  STRCMP_EQUAL("GPIO17", leak->line.c_str());
  CHECK_TRUE(leak->active_low && leak->latch);
  CHECK(leak->bias == hal_linux::LineBias::kPullUp);
  CHECK(leak->direction == hal_linux::LineDirection::kInput);
  CHECK(board.find(LineRole::kDropWeight)->direction == hal_linux::LineDirection::kOutput);
  CHECK(board.find(LineRole::kPumpLimitIn) == nullptr);
  STRCMP_EQUAL("glider-firmware", board.consumer.c_str());
  const auto sim = hal_linux::load_gpio_board(GLIDER_SOURCE_DIR "/boards/gpio/gpio_sim.toml");
  CHECK_TRUE(sim.find(LineRole::kValve)->initial_active);
}

TEST(GpioBoardFile, TheTableOfALineIsItsLocation) {
  const auto board = hal_linux::parse_gpio_board(kValid, "gpio.toml");
  STRCMP_EQUAL("gpio.toml:2:1", board.find(LineRole::kLeak)->where.c_str());
  STRCMP_EQUAL("gpio.toml:8:1", board.find(LineRole::kDropWeight)->where.c_str());
}

TEST(GpioBoardFile, ProblemsNameFileLineAndKey) {
  STRCMP_EQUAL("", error_of(kValid).c_str());
  STRCMP_CONTAINS("gpio.toml:2:1: lines: missing the required line [lines.drop_weight]",
                  error_of(std::string(kValid).substr(0, std::string(kValid).find("[lines.drop_weight]"))).c_str());
  STRCMP_CONTAINS("gpio.toml:6:8: lines.leak.bias: expected \"as-is\", \"disable\", \"pull-up\" or \"pull-down\"",
                  error_of(replaced(kValid, "\"pull-up\"", "\"pullup\"")).c_str());
  STRCMP_CONTAINS("gpio.toml:5:14: lines.leak.active_low: expected true or false",
                  error_of(replaced(kValid, "active_low = true", "active_low = \"yes\"")).c_str());
  STRCMP_CONTAINS("gpio.toml:4:8: lines.leak.line: must not be empty",
                  error_of(replaced(kValid, "\"LEAK\"", "\"\"")).c_str());
  STRCMP_CONTAINS("gpio.toml: missing required key 'lines.drop_weight.chip'",
                  error_of(replaced(kValid, "chip = \"gpiochip0\"\nline = \"BURN\"", "line = \"BURN\"")).c_str());
  STRCMP_CONTAINS("gpio.toml:10:8: lines.drop_weight.line: line \"LEAK\" is already used by [lines.leak]",
                  error_of(replaced(kValid, "\"BURN\"", "\"LEAK\"")).c_str());
}

TEST(GpioBoardFile, AMisspeltRoleOrKeyIsRefused) {
  STRCMP_CONTAINS("gpio.toml:13:8: unknown key 'lines.leek.chip'",
                  error_of(std::string(kValid) + "\n[lines.leek]\nchip = \"x\"\nline = \"y\"\n").c_str());
  STRCMP_CONTAINS("gpio.toml:7:11: unknown key 'lines.leak.latched'",
                  error_of(replaced(kValid, "latch = true", "latched = true")).c_str());
  // An output has no latch; an input has no initial level.
  STRCMP_CONTAINS("unknown key 'lines.drop_weight.latch'", error_of(std::string(kValid) + "latch = true\n").c_str());
  STRCMP_CONTAINS("unknown key 'lines.leak.initial_active'",
                  error_of(replaced(kValid, "latch = true", "initial_active = true")).c_str());
}

TEST(GpioBoardFile, TheDropWeightNeverFiresAtStartUp) {
  STRCMP_CONTAINS("gpio.toml:11:18: lines.drop_weight.initial_active: the drop weight must never fire at start-up",
                  error_of(std::string(kValid) + "initial_active = true\n").c_str());
}
