// SPDX-License-Identifier: Apache-2.0
#pragma once
// The board's digital lines through libgpiod (1.6 C++ binding, the kernel's
// GPIO character device). Every line of the board file is looked up by name
// and requested at start-up, so a missing chip or line stops the firmware
// before it flies, with the board file and line in the message. In the loop,
// read() and set() are non-blocking and do not allocate; a kernel error
// makes the sample invalid (or set() false) and is counted. Inputs are
// requested for edge events (the line must be interrupt-capable, as the
// SoC's own GPIOs are); edges are counted, and latched where the board says.
#include <array>
#include <cstdint>
#include <gpiod.hpp>
#include <memory>
#include <vector>

#include "glider/hal/clock.hpp"
#include "glider/hal/digital_io.hpp"
#include "glider/hal_linux/gpio_board.hpp"

namespace glider::hal_linux {

struct GpioInputStats {
  std::uint64_t reads = 0;
  std::uint64_t edge_events = 0;          // edge events drained from the kernel
  std::uint64_t latched_activations = 0;  // reads that reported an activation the level no longer showed
  std::uint64_t errors = 0;
};

struct GpioOutputStats {
  std::uint64_t writes = 0;
  std::uint64_t errors = 0;
};

class GpioInput final : public hal::DigitalInput {
 public:
  GpioInput(const LineConfig& config, gpiod::line line, const hal::Clock& clock);
  hal::DigitalSample read() override;
  const GpioInputStats& stats() const { return stats_; }
  const LineConfig& config() const { return config_; }

 private:
  // Drains the pending edge events without blocking: the number of
  // activations among them, -1 on a kernel error. Bounded, so a chattering
  // line cannot stall the loop.
  int drain_events();

  LineConfig config_;
  gpiod::line line_;
  const hal::Clock& clock_;
  int event_fd_;
  GpioInputStats stats_;
};

class GpioOutput final : public hal::DigitalOutput {
 public:
  GpioOutput(const LineConfig& config, gpiod::line line);
  bool set(bool active) override;
  const GpioOutputStats& stats() const { return stats_; }
  const LineConfig& config() const { return config_; }

 private:
  LineConfig config_;
  // line::set_value() builds a one-line bulk and a vector on every call;
  // both are made once here so that set() does not allocate.
  gpiod::line_bulk bulk_;
  std::vector<int> value_;
  GpioOutputStats stats_;
};

class GpioLines {
 public:
  // Start-up: looks up and requests every line of the board. Throws
  // config::ConfigError "board.toml:LINE:COL: lines.ROLE: problem" for a
  // missing chip, a missing line name or a line already in use.
  static std::unique_ptr<GpioLines> open(const GpioBoard& board, const hal::Clock& clock);

  // Null when the board has no such line (or it has the other direction).
  GpioInput* input(LineRole role);
  GpioOutput* output(LineRole role);

 private:
  GpioLines() = default;
  std::array<std::unique_ptr<GpioInput>, kLineRoleCount> inputs_;
  std::array<std::unique_ptr<GpioOutput>, kLineRoleCount> outputs_;
};

}  // namespace glider::hal_linux
