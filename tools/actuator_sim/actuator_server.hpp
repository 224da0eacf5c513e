// SPDX-License-Identifier: Apache-2.0
#pragma once
// The actuator simulator's Modbus server (libmodbus): the board's axes
// behind the default register map, on TCP (many clients) or on a serial
// device (RTU), with the fault plan applied to every request.
#include <csignal>
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
};

}  // namespace glider::sim_tools
