// SPDX-License-Identifier: Apache-2.0
// glider-bench: bench tests of the buoyancy pump and the battery slide over
// Modbus, before the glider goes in the water. Same driver as the flight
// HAL; refuses targets outside the board's limits; asks before it moves
// hardware (or --yes); progress on stderr, results on stdout, samples to CSV.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <string>

#include "bench_session.hpp"
#include "glider/cli/tool.hpp"
#include "glider/config/toml_document.hpp"
#include "glider/hal_linux/modbus_board.hpp"

namespace {

using glider::bench::BenchSession;
using glider::hal_linux::AxisConfig;

struct Options {
  std::string board_file = GLIDER_DEFAULT_MODBUS_BOARD;
  std::string tcp;
  std::string rtu;
  std::string csv;
  bool yes = false;
  std::string axis = "pump";
  double value = 0.0;
  double rate = 0.0;  // 0: the board's rate
};

class Refusal : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

void check_limits(const AxisConfig& c, double target) {
  if (target < c.min || target > c.max) {
    char text[200];
    std::snprintf(text, sizeof text, "refused: %g %s is outside the %s's limits [%g, %g] %s", target, c.unit.c_str(),
                  c.name.c_str(), c.min, c.max, c.unit.c_str());
    throw Refusal(text);
  }
}

void confirm(const Options& o, const std::string& what) {
  if (o.yes) return;
  std::fprintf(stderr, "about to %s. Move the hardware? [y/N] ", what.c_str());
  std::string answer;
  if (!std::getline(std::cin, answer) || (answer != "y" && answer != "yes")) {
    throw Refusal("not confirmed: nothing moved (--yes skips the question)");
  }
}

std::string amount(double value, const AxisConfig& c) {
  char text[64];
  std::snprintf(text, sizeof text, "%+.3f %s", value, c.unit.c_str());
  return text;
}

double rate_of(const Options& o, const AxisConfig& c) { return o.rate > 0.0 ? o.rate : c.rate; }

// Fails with a clear message when the axis does not answer at all.
glider::hal_linux::AxisStatus require_answer(BenchSession& s, glider::hal_linux::ModbusAxis& axis) {
  const auto status = s.poll(axis);
  if (!status.answered) {
    throw std::runtime_error("no answer from the " + axis.config().name + " (slave " +
                             std::to_string(axis.config().slave) + ") at " + describe(s.board().bus) + ": " +
                             status.error);
  }
  return status;
}

int cmd_status(BenchSession& s) {
  std::printf("bus    : %s\n", describe(s.board().bus).c_str());
  int answered = 0;
  for (const char* name : {"pump", "slide"}) {
    auto& axis = s.axis(name);
    const AxisConfig& c = axis.config();
    s.link().begin_cycle();
    const auto id = axis.identify();
    const auto st = s.poll(axis);
    if (!id.answered || !st.answered) {
      std::printf("%-6s : slave %d @%d: NO ANSWER (%s)\n", name, c.slave, c.base_address,
                  id.answered ? st.error : id.error);
      continue;
    }
    ++answered;
    std::printf("%-6s : slave %d @%d: %s map v%d.%d; %s; limits [%g, %g] %s\n", name, c.slave, c.base_address,
                id.recognised ? "glider actuator" : "UNKNOWN DEVICE", id.version >> 8, id.version & 0xFF,
                glider::bench::describe_status(st, c.unit).c_str(), c.min, c.max, c.unit.c_str());
  }
  if (answered == 0) throw std::runtime_error("no device answers at " + describe(s.board().bus));
  return answered == 2 ? 0 : 1;
}

void report_move(const char* what, const glider::bench::MoveOutcome& m, const AxisConfig& c, double start,
                 double target) {
  const auto metrics = glider::bench::measure_move(m.samples, start, target);
  std::printf(
      "%s %s %+.3f -> %+.3f %s: %s; travel %.1f s, rate %.3f %s/s, rise (10-90 %%) %.1f s, overshoot %.1f %%, "
      "settled %.1f s\n",
      c.name.c_str(), what, start, target, c.unit.c_str(), m.arrived ? "arrived" : m.problem.c_str(),
      metrics.travel_time_s, metrics.mean_rate, c.unit.c_str(), metrics.rise_time_s, metrics.overshoot_pct,
      metrics.settle_time_s);
  if (!m.arrived) throw std::runtime_error(c.name + ": " + m.problem);
}

// Moves to `target` after the checks; returns where it started.
double checked_move(BenchSession& s, const Options& o, const char* what, double target) {
  auto& axis = s.axis(o.axis);
  const AxisConfig& c = axis.config();
  check_limits(c, target);
  const double start = require_answer(s, axis).position;
  confirm(o, what + (" the " + c.name + " from " + amount(start, c) + " to " + amount(target, c)));
  const auto m = s.move(axis, target, rate_of(o, c));
  report_move(what, m, c, start, target);
  return start;
}

int cmd_home(BenchSession& s, const Options& o) {
  auto& axis = s.axis(o.axis);
  const AxisConfig& c = axis.config();
  const double start = require_answer(s, axis).position;
  confirm(o, "home the " + c.name + " (drive to its minimum limit switch)");
  report_move("home", s.move(axis, c.travel_min, c.max_rate, true), c, start, c.travel_min);
  return 0;
}

int cmd_step(BenchSession& s, const Options& o) {
  const double start = require_answer(s, s.axis(o.axis)).position;
  checked_move(s, o, "step", start + o.value);
  return 0;
}

int cmd_cycle(BenchSession& s, const Options& o) {
  const AxisConfig& c = s.axis(o.axis).config();
  Options asked = o;
  confirm(o, "cycle the " + c.name + " over its full travel " + amount(c.min, c) + " .. " + amount(c.max, c));
  asked.yes = true;
  checked_move(s, asked, "to-min", c.min);
  checked_move(s, asked, "full-travel", c.max);
  checked_move(s, asked, "full-travel", c.min);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-bench",
                         "Bench tests of the Modbus pump and slide (the flight driver, the board's limits)");
  CLI::App& app = tool.app();
  app.require_subcommand(1);
  Options o;
  app.add_option("--board", o.board_file, "board file (bus, axes, limits)")->check(CLI::ExistingFile);
  auto* tcp = app.add_option("--tcp", o.tcp, "Modbus TCP device at HOST:PORT (overrides the board)")
                  ->check(CLI::Validator(
                      [](std::string& text) { return glider::hal_linux::tcp_endpoint_problem(text); }, "HOST:PORT"));
  app.add_option("--rtu", o.rtu, "Modbus RTU on this serial device (overrides the board)")->excludes(tcp);
  app.add_option("--csv", o.csv, "log every sample of the moves to this CSV file");
  app.add_flag("--yes,-y", o.yes, "do not ask before moving hardware");
  const auto axis_arg = [&](CLI::App* sub) {
    sub->add_option("axis", o.axis, "pump or slide")->required()->check(CLI::IsMember({"pump", "slide"}));
  };
  auto* status = app.add_subcommand("status", "identify both axes and read their status");
  auto* home = app.add_subcommand("home", "drive an axis to its minimum limit switch (its reference)");
  axis_arg(home);
  auto* move = app.add_subcommand("move", "move an axis to a volume (cc) or position (in)");
  axis_arg(move);
  // Finite here; the board's limits of the axis are checked before anything moves.
  tool.set_leading(
      tool.add_number(move, "target", o.value, {-1e4, 1e4, "cc or in"}, "cc for the pump, in for the slide")
          ->required(),
      {"pump"});
  auto* step = app.add_subcommand("step", "step response: move by DELTA from where it is; rise, overshoot, settling");
  axis_arg(step);
  tool.set_leading(tool.add_number(step, "delta", o.value, {-1e4, 1e4, "cc or in"}, "step size, cc or in")->required(),
                   {"pump"});
  auto* cycle = app.add_subcommand("cycle", "full-travel cycle min -> max -> min: travel times and rates");
  axis_arg(cycle);
  // 0 is not a rate: the option absent means the board's rate.
  for (auto* sub : {move, step, cycle}) {
    tool.add_number(sub, "--rate", o.rate, {1e-3, 1e3, "cc/s or in/s"}, "unit/s (default: the board's rate)");
  }
  return tool.run(argc, argv, [&]() -> int {
    try {
      auto board = glider::hal_linux::load_modbus_board(o.board_file);
      if (!o.tcp.empty()) glider::hal_linux::use_tcp_endpoint(board.bus, o.tcp);
      if (!o.rtu.empty()) glider::hal_linux::use_rtu_device(board.bus, o.rtu);
      BenchSession session(board, o.csv);
      if (!session.warning().empty()) std::fprintf(stderr, "glider-bench: warning: %s\n", session.warning().c_str());
      int code = 0;
      if (*status) {
        code = cmd_status(session);
      } else if (*home) {
        code = cmd_home(session, o);
      } else if (*move) {
        checked_move(session, o, "move", o.value);
      } else if (*step) {
        code = cmd_step(session, o);
      } else if (*cycle) {
        code = cmd_cycle(session, o);
      }
      session.finish(code == 0 ? "complete" : "stopped failed");
      return code;
    } catch (const Refusal& refusal) {
      // A command outside the board's limits, or not confirmed: the user's command line.
      throw glider::cli::ToolError(glider::cli::kUsage, refusal.what());
    }
  });
}
