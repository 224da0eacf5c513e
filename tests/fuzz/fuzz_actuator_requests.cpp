// SPDX-License-Identifier: Apache-2.0
// The actuator simulator's request handling on an arbitrary client byte
// stream: framing (tcp_frame_size), the request checks and the register map
// (libmodbus' reply) of the real ActuatorServer, replying on a socket pair.
// After every input the server must still answer a good read.
#include <sys/socket.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>

#include "actuator_server.hpp"
#include "glider/hal_linux/modbus_board.hpp"
#include "modbus_request.hpp"

namespace {

struct Fixture {
  std::unique_ptr<glider::sim_tools::ActuatorServer> server;
  int sockets[2] = {-1, -1};

  Fixture() {
    glider::sim_tools::ServerOptions options;
    options.board = glider::hal_linux::load_modbus_board(GLIDER_SOURCE_DIR "/boards/actuators/default_modbus.toml");
    options.board.bus.transport = glider::hal_linux::Transport::kTcp;
    options.board.bus.host = "127.0.0.1";
    options.board.bus.port = 0;  // ephemeral: nothing connects to it
    server = std::make_unique<glider::sim_tools::ActuatorServer>(options);
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK, 0, sockets) != 0) std::abort();
  }
  // What the server wrote; the replies themselves are libmodbus' business.
  std::size_t drain() const {
    std::uint8_t buffer[4096];
    std::size_t total = 0;
    for (ssize_t n; (n = read(sockets[1], buffer, sizeof buffer)) > 0;) total += static_cast<std::size_t>(n);
    return total;
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace st = glider::sim_tools;
  static Fixture fixture;
  std::size_t used = 0;
  while (used < size) {
    const std::size_t frame = st::tcp_frame_size(data + used, size - used);
    if (frame == st::kFrameIncomplete || frame == st::kFrameMalformed) break;  // the server drops such a client
    fixture.server->serve_frame(fixture.sockets[0], data + used, frame);
    fixture.drain();
    used += frame;
  }
  // State intact: a read of the pump's block (slave 1 at 0) is still answered.
  const std::uint8_t good[] = {0, 1, 0, 0, 0, 6, 1, 3, 0, 0, 0, 8};
  fixture.server->serve_frame(fixture.sockets[0], good, sizeof good);
  if (fixture.drain() != 9 + 16) std::abort();
  return 0;
}
