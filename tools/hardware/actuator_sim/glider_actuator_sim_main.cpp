// SPDX-License-Identifier: Apache-2.0
// glider-actuator-sim: a Modbus server that behaves like the board's pump
// and slide controller (default register map, rate and travel limits,
// limit switches, injectable faults). For the tests, the bench tool's demo
// and SIL on the target.
#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <stdexcept>

#include "actuator_server.hpp"
#include "glider/cli/tool.hpp"
#include "glider/config/toml_document.hpp"
#include "glider/hal_linux/modbus_board.hpp"

namespace {

volatile std::sig_atomic_t g_stop = 0;
void request_stop(int) { g_stop = 1; }

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-actuator-sim",
                         "Modbus actuator simulator: the default register map with actuator dynamics and faults");
  CLI::App& app = tool.app();
  std::string board_file = GLIDER_DEFAULT_MODBUS_BOARD;
  std::string tcp;
  std::string rtu;
  std::vector<std::string> faults;
  double time_scale = 1.0;
  app.add_option("--board", board_file, "board file (bus settings, axes)")->check(CLI::ExistingFile);
  auto* tcp_option =
      app.add_option("--tcp", tcp,
                     "serve Modbus TCP on HOST:PORT (port 0: any free port); "
                     "default 127.0.0.1 and the board's port")
          ->check(CLI::Validator([](std::string& text) { return glider::hal_linux::tcp_endpoint_problem(text); },
                                 "HOST:PORT"));
  app.add_option("--rtu", rtu, "serve Modbus RTU on this serial device (e.g. one end of a socat pty pair)")
      ->excludes(tcp_option);
  app.add_option("--fault", faults, "inject a fault: stall:S, silent:N, noise:N, exception:N, slow:MS (repeatable)");
  tool.add_number("--time-scale", time_scale, {0.01, 1000.0, ""},
                  "simulated seconds per real second (faster bench demos)");
  return tool.run(argc, argv, [&]() -> int {
    glider::sim_tools::ServerOptions options;
    options.board = glider::hal_linux::load_modbus_board(board_file);
    options.time_scale = time_scale;
    glider::hal_linux::BusConfig& bus = options.board.bus;
    if (!rtu.empty()) {
      glider::hal_linux::use_rtu_device(bus, rtu);
    } else if (!tcp.empty()) {
      glider::hal_linux::use_tcp_endpoint(bus, tcp);
    } else {
      // The board's host is where the glider finds the device; the
      // simulator stays on loopback unless told otherwise.
      glider::hal_linux::use_tcp_endpoint(bus, "127.0.0.1:" + std::to_string(bus.port));
    }
    for (const std::string& spec : faults) options.faults.add(spec);

    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
    std::signal(SIGPIPE, SIG_IGN);  // a client that vanished mid-reply
    glider::sim_tools::ActuatorServer server(options);
    const auto& board = options.board;
    std::printf(
        "actuator-sim: serving %s (pump: slave %d at register %d, slide: slave %d at register %d; faults: %s)\n",
        server.endpoint().c_str(), board.pump.slave, board.pump.base_address, board.slide.slave,
        board.slide.base_address, options.faults.describe().c_str());
    if (!server.warning().empty()) std::printf("actuator-sim: warning: %s\n", server.warning().c_str());
    std::fflush(stdout);
    server.run(g_stop);
    std::printf("actuator-sim: stopped\n");
    return static_cast<int>(glider::cli::kOk);
  });
}
