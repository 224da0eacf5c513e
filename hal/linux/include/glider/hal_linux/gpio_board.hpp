// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a GPIO board file says (boards/gpio/README.md): for each digital line
// the glider uses, the chip and the line NAME it has on this board (never an
// offset: offsets change between kernels and device trees), its direction,
// active level, bias and, for inputs, whether activations are latched.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glider::hal_linux {

enum class LineDirection { kInput, kOutput };
enum class LineBias { kAsIs, kDisabled, kPullUp, kPullDown };

// The lines a glider board can have. leak and drop_weight are required (the
// firmware's abort path needs them); the others are optional.
enum class LineRole {
  kLeak,
  kDropWeight,
  kPumpEnable,
  kValve,
  kPumpLimitIn,
  kPumpLimitOut,
  kSlideLimitFwd,
  kSlideLimitAft
};
constexpr int kLineRoleCount = 8;
const char* role_key(LineRole role);  // "leak", "drop_weight", ...

struct LineConfig {
  LineRole role = LineRole::kLeak;
  std::string chip;                                 // name ("gpiochip0"), path, label or number (libgpiod's lookup)
  std::string line;                                 // the line's name on that chip (gpio-line-names)
  LineDirection direction = LineDirection::kInput;  // fixed by the role
  bool active_low = false;
  LineBias bias = LineBias::kAsIs;
  // Inputs: requested for edge events; an activation (the logical edge,
  // whatever the wiring's polarity) since the last read is reported once,
  // even when the line has gone back by then (a short leak-detector pulse).
  bool latch = false;
  bool initial_active = false;  // outputs: level set when the line is requested
  std::string where;            // "file:line:column" of the [lines.ROLE] table, for start-up errors
};

struct GpioBoard {
  std::string source;               // file it was read from
  std::string consumer = "glider";  // label the kernel shows for our requests
  std::vector<LineConfig> lines;    // in LineRole order, only those present

  const LineConfig* find(LineRole role) const;
};

// Init-time only: throws config::ConfigError naming file, line and problem.
GpioBoard load_gpio_board(const std::filesystem::path& path);
GpioBoard parse_gpio_board(const std::string& text, const std::string& source_name);

}  // namespace glider::hal_linux
