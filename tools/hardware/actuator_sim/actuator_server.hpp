// SPDX-License-Identifier: Apache-2.0
#pragma once
// The actuator simulator's Modbus server (libmodbus): the board's axes
// behind the default register map, on TCP (many clients) or on a serial
// device (RTU), with the fault plan applied to every request.
#include <csignal>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fault_plan.hpp"
#include "glider/hal_linux/modbus_board.hpp"
#include "simulated_axis.hpp"

struct _modbus;
struct _modbus_mapping_t;

namespace glider::sim_tools {

struct ServerOptions {
  hal_linux::ModbusBoard board;  // bus says where to serve
  FaultPlan faults;
  double time_scale = 1.0;  // simulated seconds per real second
  // TCP: clients served at once; one more is accepted and closed at once
  // (its connect succeeds, its first read sees the end of the stream), and
  // the refusal is counted and said on stderr.
  int max_clients = 64;
  // TCP: a frame started must be whole within this, and a client silent for
  // idle_timeout_s is closed: a slow or stuck client never holds a slot.
  double frame_timeout_s = 2.0;
  double idle_timeout_s = 120.0;
};

struct ServerStats {
  std::uint64_t accepted = 0;
  std::uint64_t refused = 0;     // over max_clients
  std::uint64_t timed_out = 0;   // frame or idle timeout
  std::uint64_t malformed = 0;   // not a Modbus TCP frame: client dropped
  std::uint64_t exceptions = 0;  // requests answered with an exception by the checks
  std::uint64_t requests = 0;    // frames handed to the register map
};

class ActuatorServer {
 public:
  // Throws std::runtime_error when it cannot serve (bad address, device).
  explicit ActuatorServer(const ServerOptions& options);
  ~ActuatorServer();
  ActuatorServer(const ActuatorServer&) = delete;
  ActuatorServer& operator=(const ActuatorServer&) = delete;

  // "tcp 127.0.0.1:PORT" with the port actually bound (0 = ephemeral).
  const std::string& endpoint() const { return endpoint_; }
  const std::string& warning() const { return warning_; }
  // Serves until `stop` becomes non-zero (a signal handler sets it).
  void run(const volatile std::sig_atomic_t& stop);
  // Answers one whole Modbus TCP frame on socket `fd`: the checks of
  // modbus_request.hpp, then the register map. The TCP loop calls it; the
  // fuzz target calls it on a socket pair.
  void serve_frame(int fd, const std::uint8_t* frame, std::size_t length);
  const ServerStats& stats() const { return stats_; }

 private:
  struct Axis {
    int slave;
    int base;
    SimulatedAxis model;
  };
  void serve_tcp(const volatile std::sig_atomic_t& stop);
  void serve_rtu(const volatile std::sig_atomic_t& stop);
  void handle(const std::uint8_t* query, int length);
  void advance();
  bool writes_read_only(int slave, int address, int count) const;

  ServerOptions options_;
  _modbus* context_ = nullptr;
  int listen_socket_ = -1;
  std::map<int, _modbus_mapping_t*> mappings_;  // by slave id
  std::vector<Axis> axes_;
  FaultInjector faults_;
  std::string endpoint_;
  std::string warning_;
  double last_time_s_ = 0.0;
  ServerStats stats_;
};

}  // namespace glider::sim_tools
