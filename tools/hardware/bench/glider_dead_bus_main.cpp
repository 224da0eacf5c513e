// SPDX-License-Identifier: Apache-2.0
// glider-dead-bus: how long the flight loop blocks per cycle when the
// actuator bus is dead. Each cycle does the most Modbus work a firmware
// cycle can do (FlightSoftware::run: read pump, read slide, command pump,
// command slide, the commands only when the set-point changes; here every
// cycle) and is timed on CLOCK_MONOTONIC. Prints figures; never judges them
// (timing thresholds do not belong in tests).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

#include "glider/cli/tool.hpp"
#include "glider/hal_linux/modbus_actuators.hpp"
#include "glider/hal_linux/modbus_board.hpp"

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-dead-bus", "Worst-case blocking of one control cycle on a dead Modbus bus");
  CLI::App& app = tool.app();
  std::string board_file = GLIDER_DEFAULT_MODBUS_BOARD;
  std::string tcp;
  std::string rtu;
  int cycles = 10;
  std::string label = "dead bus";
  app.add_option("--board", board_file, "board file")->check(CLI::ExistingFile);
  auto* tcp_option =
      app.add_option("--tcp", tcp, "HOST:PORT")
          ->check(CLI::Validator([](std::string& text) { return glider::hal_linux::tcp_endpoint_problem(text); },
                                 "HOST:PORT"));
  app.add_option("--rtu", rtu, "serial device")->excludes(tcp_option);
  tool.add_integer("--cycles", cycles, 1, 1'000'000, "", "control cycles to time");
  app.add_option("--label", label, "what the bus is (for the report line)");
  return tool.run(argc, argv, [&]() -> int {
    auto board = glider::hal_linux::load_modbus_board(board_file);
    if (!tcp.empty()) glider::hal_linux::use_tcp_endpoint(board.bus, tcp);
    if (!rtu.empty()) glider::hal_linux::use_rtu_device(board.bus, rtu);
    std::string warning;
    std::string error;
    auto link = glider::hal_linux::ModbusLink::open(board.bus, warning, error);
    if (!link) throw std::runtime_error(error);
    glider::hal_linux::ModbusAxis pump_axis(*link, board.pump);
    glider::hal_linux::ModbusAxis slide_axis(*link, board.slide);
    glider::hal_linux::MonotonicClock clock;
    glider::hal_linux::ModbusBuoyancyPump pump(pump_axis, clock);
    glider::hal_linux::ModbusBatterySlide slide(slide_axis, clock);

    double worst_ms = 0.0;
    double total_ms = 0.0;
    int faults = 0;
    for (int i = 0; i < cycles; ++i) {
      const auto start = std::chrono::steady_clock::now();
      link->begin_cycle();  // the platform's cycle start
      const auto p = pump.read_volume_cc();
      const auto b = slide.read_position_in();
      pump.command_volume_cc(100.0 + i);  // a new set-point every cycle: the worst case
      slide.command_position_in(0.5);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      worst_ms = std::max(worst_ms, ms);
      total_ms += ms;
      if (p.fault || b.fault) ++faults;
      // Sleep to the next period like the executive (not timed).
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    const auto& st = link->stats();
    std::printf(
        "%-34s %s: worst %.1f ms, mean %.1f ms per cycle over %d cycles (budget %d ms, timeout %d+%d ms, "
        "retries %d); faults reported in %d/%d cycles; %llu attempts, %llu refused by the budget; last "
        "error: %s\n",
        label.c_str(), describe(board.bus).c_str(), worst_ms, total_ms / cycles, cycles, board.bus.cycle_budget_ms,
        board.bus.response_timeout_ms, board.bus.byte_timeout_ms, board.bus.retries, faults, cycles,
        static_cast<unsigned long long>(st.attempts), static_cast<unsigned long long>(st.budget_refusals),
        link->last_error());
    return glider::cli::kOk;
  });
}
