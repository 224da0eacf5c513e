// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/gpio_lines.hpp"

#include <linux/gpio.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <exception>
#include <string>
#include <system_error>

#include "glider/config/toml_document.hpp"

namespace glider::hal_linux {
namespace {

// A leak detector or limit switch bouncing for a whole cycle gives a few
// dozen edges at most; past this the rest wait for the next cycle.
constexpr int kMaxEventsPerRead = 64;

std::bitset<32> request_flags(const LineConfig& config) {
  std::bitset<32> flags;
  if (config.active_low) flags |= gpiod::line_request::FLAG_ACTIVE_LOW;
  switch (config.bias) {
    case LineBias::kAsIs:
      break;
    case LineBias::kDisabled:
      flags |= gpiod::line_request::FLAG_BIAS_DISABLE;
      break;
    case LineBias::kPullUp:
      flags |= gpiod::line_request::FLAG_BIAS_PULL_UP;
      break;
    case LineBias::kPullDown:
      flags |= gpiod::line_request::FLAG_BIAS_PULL_DOWN;
      break;
  }
  return flags;
}

[[noreturn]] void fail(const LineConfig& config, const std::string& problem) {
  throw config::ConfigError(config.where + ": lines." + role_key(config.role) + ": " + problem);
}

gpiod::chip open_chip(const LineConfig& config) {
  try {
    gpiod::chip chip(config.chip, gpiod::chip::OPEN_LOOKUP);
    if (chip) return chip;
  } catch (const std::system_error&) {
    // reported below: libgpiod says only "No such file or directory"
  }
  fail(config, "no GPIO chip \"" + config.chip + "\" (looked up as a name, path, label and number)");
}

gpiod::line find_and_request(const LineConfig& config, const std::string& consumer) {
  const gpiod::chip chip = open_chip(config);
  gpiod::line line;
  try {
    line = chip.find_line(config.line);
  } catch (const std::system_error& error) {
    fail(config, "looking up line \"" + config.line + "\" on " + chip.name() + ": " + error.what());
  }
  if (!line)
    fail(config, "chip \"" + config.chip + "\" (" + chip.name() + ") has no line named \"" + config.line + "\"");
  gpiod::line_request request;
  request.consumer = consumer;
  request.flags = request_flags(config);
  if (config.direction == LineDirection::kOutput) {
    request.request_type = gpiod::line_request::DIRECTION_OUTPUT;
  } else {
    // Every input is an event request, latched or not: its file descriptor is
    // what the loop reads the level from (see GpioInput::read()).
    request.request_type = gpiod::line_request::EVENT_BOTH_EDGES;
  }
  try {
    line.request(request, config.initial_active ? 1 : 0);
  } catch (const std::system_error& error) {
    const std::string holder = line.is_used() ? " (in use by \"" + line.consumer() + "\")" : "";
    fail(config, "cannot request line \"" + config.line + "\" on " + chip.name() + holder + ": " + error.what());
  }
  return line;
}

}  // namespace

GpioInput::GpioInput(const LineConfig& config, gpiod::line line, const hal::Clock& clock)
    : config_(config), line_(std::move(line)), clock_(clock), event_fd_(line_.event_get_fd()) {}

int GpioInput::drain_events() {
  int activations = 0;
  pollfd pending{event_fd_, POLLIN, 0};
  for (int i = 0; i < kMaxEventsPerRead && ::poll(&pending, 1, 0) == 1; ++i) {
    if ((pending.revents & POLLIN) == 0) return -1;  // POLLERR/POLLHUP: the chip went away
    gpioevent_data event{};
    if (::read(event_fd_, &event, sizeof event) != static_cast<ssize_t>(sizeof event)) return -1;
    ++stats_.edge_events;
    // The kernel reports edges in the logical sense (active-low applied).
    if (event.id == GPIOEVENT_EVENT_RISING_EDGE) ++activations;
  }
  return activations;
}

// libgpiod's line::get_value() builds a line_bulk and a vector per call
// (3 allocations, measured in tests/gpio_kernel), so the loop reads the
// level and the events itself, from the request's file descriptor (the
// kernel's v1 line-event uAPI that libgpiod 1.6 requested it with): two
// non-blocking system calls, no allocation, no exception.
hal::DigitalSample GpioInput::read() {
  hal::DigitalSample sample;
  ++stats_.reads;
  const int activations = drain_events();
  gpiohandle_data level{};
  if (activations < 0 || ::ioctl(event_fd_, GPIOHANDLE_GET_LINE_VALUES_IOCTL, &level) != 0) {
    ++stats_.errors;  // the kernel refused (device gone): not a value
  } else {
    const bool active = level.values[0] != 0;
    const bool latched = config_.latch && activations > 0;
    if (latched && !active) ++stats_.latched_activations;
    sample.active = active || latched;
    sample.valid = true;
  }
  sample.time_us = clock_.now_us();
  return sample;
}

GpioOutput::GpioOutput(const LineConfig& config, gpiod::line line)
    : config_(config), bulk_(std::vector<gpiod::line>{std::move(line)}), value_(1, 0) {}

bool GpioOutput::set(bool active) {
  value_[0] = active ? 1 : 0;
  try {
    bulk_.set_values(value_);
    ++stats_.writes;
    return true;
  } catch (const std::exception&) {
    ++stats_.errors;
    return false;
  }
}

std::unique_ptr<GpioLines> GpioLines::open(const GpioBoard& board, const hal::Clock& clock) {
  std::unique_ptr<GpioLines> lines(new GpioLines());
  for (const LineConfig& config : board.lines) {
    gpiod::line line = find_and_request(config, board.consumer);
    const auto index = static_cast<std::size_t>(config.role);
    if (config.direction == LineDirection::kOutput) {
      lines->outputs_[index] = std::make_unique<GpioOutput>(config, std::move(line));
    } else {
      lines->inputs_[index] = std::make_unique<GpioInput>(config, std::move(line), clock);
    }
  }
  return lines;
}

GpioInput* GpioLines::input(LineRole role) { return inputs_[static_cast<std::size_t>(role)].get(); }
GpioOutput* GpioLines::output(LineRole role) { return outputs_[static_cast<std::size_t>(role)].get(); }

}  // namespace glider::hal_linux
