// SPDX-License-Identifier: Apache-2.0
// The actuator simulator under hostile clients, on loopback: 2,000
// connection attempts, 50 slow clients (one byte every 0.4 s), a burst of
// malformed and oversize frames, all while a well-behaved libmodbus client
// reads its block in a loop. That client must never fail and its slowest
// request must stay under kLatencyBoundMs (the old select() server let one
// slow client block everyone for seconds). Every loop is bounded in count
// and in time. The figures are printed; the bound is the only judgement.
#include <CppUTest/TestHarness.h>
#include <arpa/inet.h>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "actuator_server.hpp"
#include "glider/hal_linux/modbus_board.hpp"

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kLatencyBoundMs = 250.0;
constexpr int kConnectionAttempts = 2000;
constexpr int kSlowClients = 50;
constexpr auto kTestLength = std::chrono::seconds(6);

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A blocking loopback connection, or -1.
int connect_to(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  timeval timeout{1, 0};
  setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
  setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

std::vector<std::uint8_t> frame(std::uint16_t id, const std::vector<std::uint8_t>& pdu) {
  const auto length = static_cast<std::uint16_t>(pdu.size() + 1);
  std::vector<std::uint8_t> out;
  out.reserve(7 + pdu.size());
  for (const int byte : {id >> 8, id & 0xff, 0, 0, length >> 8, length & 0xff, 1}) {
    out.push_back(static_cast<std::uint8_t>(byte));
  }
  for (const std::uint8_t byte : pdu) out.push_back(byte);
  return out;
}

// Sends `request` on a new connection; the reply bytes (empty if none within 1 s or closed).
std::vector<std::uint8_t> ask(int port, const std::vector<std::uint8_t>& request) {
  const int fd = connect_to(port);
  if (fd == -1) return {};
  std::vector<std::uint8_t> reply(300);
  ssize_t got = -1;
  if (send(fd, request.data(), request.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(request.size())) {
    got = recv(fd, reply.data(), reply.size(), 0);
  }
  close(fd);
  reply.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
  return reply;
}

int port_of(const std::string& endpoint) { return std::stoi(endpoint.substr(endpoint.rfind(':') + 1)); }

}  // namespace

TEST_GROUP(ActuatorSimLoad){};

TEST(ActuatorSimLoad, WellBehavedClientKeepsItsLatencyUnderHostileClients) {
  glider::sim_tools::ServerOptions options;
  options.board = glider::hal_linux::load_modbus_board(GLIDER_SOURCE_DIR "/boards/actuators/default_modbus.toml");
  glider::hal_linux::use_tcp_endpoint(options.board.bus, "127.0.0.1:0");
  options.max_clients = 64;
  options.frame_timeout_s = 1.0;
  glider::sim_tools::ActuatorServer server(options);
  const int port = port_of(server.endpoint());
  volatile std::sig_atomic_t stop = 0;
  std::thread serving([&] { server.run(stop); });

  // The well-behaved client connects first and reads its block until the others are done.
  modbus_t* good = modbus_new_tcp("127.0.0.1", port);
  modbus_set_response_timeout(good, 1, 0);
  CHECK(modbus_connect(good) == 0);
  modbus_set_slave(good, 1);
  std::atomic<bool> others_done{false};
  std::vector<double> latencies_ms;
  int failures = 0;
  std::thread reader([&] {
    const auto end = Clock::now() + kTestLength + std::chrono::seconds(4);
    std::uint16_t registers[8];
    while (!others_done && Clock::now() < end && latencies_ms.size() < 200000) {
      const auto start = Clock::now();
      if (modbus_read_registers(good, 0, 8, registers) != 8) ++failures;
      latencies_ms.push_back(ms_since(start));
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  });

  // 50 slow clients: one byte of a valid frame every 0.4 s; dropped by the
  // frame timeout, they reconnect and start again.
  std::atomic<int> slow_dropped{0};
  std::thread slow([&] {
    const std::vector<std::uint8_t> request = frame(7, {3, 0, 0, 0, 8});
    std::vector<int> fds(kSlowClients, -1);
    std::vector<std::size_t> sent(kSlowClients, 0);
    const auto end = Clock::now() + kTestLength;
    while (Clock::now() < end) {
      for (int i = 0; i < kSlowClients; ++i) {
        if (fds[i] == -1) {
          fds[i] = connect_to(port);
          sent[i] = 0;
        }
        if (fds[i] == -1) continue;
        const std::uint8_t byte = request[sent[i] % request.size()];
        if (send(fds[i], &byte, 1, MSG_NOSIGNAL | MSG_DONTWAIT) != 1) {
          ++slow_dropped;
          close(fds[i]);
          fds[i] = -1;
        } else {
          ++sent[i];
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(400));
    }
    for (int fd : fds) {
      if (fd != -1) close(fd);
    }
  });

  // 2,000 connection attempts, each closed at once.
  int connected = 0;
  std::thread flood([&] {
    const auto end = Clock::now() + kTestLength;
    for (int i = 0; i < kConnectionAttempts && Clock::now() < end; ++i) {
      const int fd = connect_to(port);
      if (fd != -1) {
        ++connected;
        close(fd);
      }
    }
  });

  // The malformed burst, then the oversize read answered with an exception.
  int burst = 0;
  std::thread malformed([&] {
    const std::vector<std::vector<std::uint8_t>> bad{
        frame(1, {3, 0, 0, 0xff, 0xff}),                // read 65,535 registers
        frame(2, {0x2b, 0x0e, 1, 0}),                   // a function the map does not have
        frame(3, {16, 0, 1, 0, 3, 2, 0, 1}),            // write 3 registers, 2 bytes
        {0, 4, 0, 9, 0, 6, 1, 3, 0, 0, 0, 8},           // protocol id 9
        {0, 5, 0, 0, 0xff, 0xff, 1, 3},                 // length field 65,535
        {0xde, 0xad, 0xbe, 0xef, 0, 0, 0, 0, 1, 2, 3},  // noise
    };
    for (int round = 0; round < 50; ++round) {
      for (const auto& request : bad) {
        ask(port, request);
        ++burst;
      }
    }
  });

  flood.join();
  slow.join();
  malformed.join();
  // The state is intact: an oversize read gets the exception, and the next
  // client's first request is answered.
  const std::vector<std::uint8_t> exception = ask(port, frame(9, {3, 0, 0, 0xff, 0xff}));
  const std::vector<std::uint8_t> expected{0, 9, 0, 0, 0, 3, 1, 0x83, 3};
  CHECK(exception == expected);
  const std::vector<std::uint8_t> next = ask(port, frame(10, {3, 0, 0, 0, 8}));
  LONGS_EQUAL(9 + 16, next.size());
  others_done = true;
  reader.join();
  modbus_close(good);
  modbus_free(good);
  stop = 1;
  serving.join();

  std::sort(latencies_ms.begin(), latencies_ms.end());
  const auto at = [&](double q) { return latencies_ms[static_cast<std::size_t>(q * (latencies_ms.size() - 1))]; };
  const auto& stats = server.stats();
  std::printf(
      "\nwell-behaved client: %zu requests, %d failed, latency p50 %.2f ms, p99 %.2f ms, max %.2f ms (bound %.0f ms)\n"
      "server: %llu accepted, %llu refused (cap %d), %llu timed out, %llu malformed dropped, %llu exception "
      "replies, %llu requests\n"
      "clients: %d of %d connection attempts connected, %d slow-client drops, %d malformed frames sent\n",
      latencies_ms.size(), failures, at(0.5), at(0.99), latencies_ms.back(), kLatencyBoundMs,
      static_cast<unsigned long long>(stats.accepted), static_cast<unsigned long long>(stats.refused),
      options.max_clients, static_cast<unsigned long long>(stats.timed_out),
      static_cast<unsigned long long>(stats.malformed), static_cast<unsigned long long>(stats.exceptions),
      static_cast<unsigned long long>(stats.requests), connected, kConnectionAttempts, slow_dropped.load(), burst);
  LONGS_EQUAL(0, failures);
  CHECK(latencies_ms.size() > 100);
  CHECK(latencies_ms.back() < kLatencyBoundMs);
  CHECK(stats.timed_out > 0);   // the slow clients were cut off
  CHECK(stats.malformed > 0);   // the bad headers dropped their clients
  CHECK(stats.exceptions > 0);  // oversize and unknown requests answered
}
