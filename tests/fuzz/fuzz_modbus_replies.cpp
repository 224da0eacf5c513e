// SPDX-License-Identifier: Apache-2.0
// Replies from the bus, as the glider's Modbus stack takes them: the real
// ModbusLink (libmodbus client over loopback TCP) asks, a responder thread
// answers every request with the fuzz input (its transaction id set to the
// request's, so the reply is judged on its content), and the Keller depth
// sensor and an actuator axis decode it. A value they accept must be a
// finite depth or position inside the axis' travel.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "glider/hal_linux/keller_depth.hpp"
#include "glider/hal_linux/modbus_actuators.hpp"
#include "glider/hal_linux/modbus_axis.hpp"
#include "glider/hal_linux/modbus_link.hpp"

namespace {

namespace hl = glider::hal_linux;

bool read_exactly(int fd, std::uint8_t* out, std::size_t size) {
  for (std::size_t got = 0; got < size;) {
    const ssize_t n = read(fd, out + got, size - got);
    if (n <= 0) return false;
    got += static_cast<std::size_t>(n);
  }
  return true;
}

class Responder {
 public:
  Responder() {
    listener_ = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t size = sizeof address;
    if (bind(listener_, reinterpret_cast<sockaddr*>(&address), size) != 0 || listen(listener_, 4) != 0 ||
        getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &size) != 0) {
      std::abort();
    }
    port_ = ntohs(address.sin_port);
    std::thread([this] { serve(); }).detach();  // lives as long as the fuzzer process
  }
  int port() const { return port_; }
  void set_reply(const std::uint8_t* data, std::size_t size) {
    const std::lock_guard<std::mutex> lock(mutex_);
    reply_.assign(data, data + size);
  }

 private:
  void serve() {
    for (;;) {
      const int fd = accept(listener_, nullptr, nullptr);
      if (fd == -1) continue;
      std::uint8_t header[7];
      std::uint8_t body[260];
      while (read_exactly(fd, header, sizeof header)) {
        const std::size_t rest = ((static_cast<std::size_t>(header[4]) << 8) | header[5]);
        if (rest < 1 || rest - 1 > sizeof body || !read_exactly(fd, body, rest - 1)) break;
        std::vector<std::uint8_t> reply;
        {
          const std::lock_guard<std::mutex> lock(mutex_);
          reply = reply_;
        }
        if (reply.size() >= 2) {
          reply[0] = header[0];
          reply[1] = header[1];
        }
        if (!reply.empty() && write(fd, reply.data(), reply.size()) < 0) break;
      }
      close(fd);
    }
  }

  int listener_ = -1;
  int port_ = 0;
  std::mutex mutex_;
  std::vector<std::uint8_t> reply_;
};

struct Fixture {
  Responder responder;
  std::unique_ptr<hl::ModbusLink> link;
  hl::MonotonicClock clock;
  hl::AxisConfig axis_config;

  Fixture() {
    hl::BusConfig bus;
    bus.port = responder.port();
    bus.response_timeout_ms = 5;  // the responder answers at once; a short reply just times out
    bus.byte_timeout_ms = 2;
    bus.retries = 0;
    bus.cycle_budget_ms = 1000;
    std::string warning, error;
    link = hl::ModbusLink::open(bus, warning, error);
    if (!link) std::abort();
    axis_config = {"pump", "cc", 1, 0, 10.0, -250.0, 250.0, 4.0, -260.0, 260.0, 5.0};
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Never destroyed: the responder thread outlives LLVMFuzzerTestOneInput to the process' end.
  static Fixture& fixture = *new Fixture;
  fixture.responder.set_reply(data, size);
  fixture.link->begin_cycle();
  hl::KellerDepthSensor keller(*fixture.link, hl::KellerConfig{}, fixture.clock);
  const glider::hal::DepthSample depth = keller.read();
  if (depth.valid && !std::isfinite(depth.depth_m)) std::abort();
  hl::ModbusAxis axis(*fixture.link, fixture.axis_config);
  const glider::hal::ActuatorReading reading = axis.read(0);
  const double tolerance = 1.0 / fixture.axis_config.counts_per_unit;
  if (reading.valid && !(reading.position >= fixture.axis_config.travel_min - tolerance &&
                         reading.position <= fixture.axis_config.travel_max + tolerance)) {
    std::abort();
  }
  (void)axis.identify();
  return 0;
}
