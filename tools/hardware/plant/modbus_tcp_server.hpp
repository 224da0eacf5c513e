// SPDX-License-Identifier: Apache-2.0
#pragma once
// A Modbus TCP server for many clients in one thread: poll() readiness (no
// select() and its FD_SETSIZE limit), each client's bytes framed by the MBAP
// header (the actuator simulator's tcp_frame_size), requests outside the
// register map's functions and quantities refused (its request_exception),
// the rest answered by libmodbus (register access, bad addresses). A client that
// leaves a request unfinished longer than the request timeout, or says
// nothing for the idle timeout, is disconnected; connections beyond the cap
// are accepted and closed at once (counted), so the listen queue never
// stalls the well-behaved ones. Each read that carried requests is timed
// from the request's arrival in the kernel (SO_TIMESTAMPNS) to its answer:
// how late the plant answered (the answer observer).
#include <modbus/modbus.h>
#include <poll.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace glider::plant {

struct TcpServerOptions {
  std::string host = "127.0.0.1";  // loopback only by default
  int port = 0;                    // 0: any free port (port() says which)
  int max_clients = 64;
  int request_timeout_ms = 1000;  // first byte of a request to its last
  int idle_timeout_ms = 60'000;   // no request at all
};

struct TcpServerStats {
  unsigned long long accepted = 0;
  unsigned long long refused = 0;  // over the connection cap
  unsigned long long requests = 0;
  unsigned long long exceptions = 0;  // requests answered with an exception (our own checks)
  unsigned long long malformed = 0;   // bad MBAP header: client dropped
  unsigned long long timed_out = 0;   // request or idle timeout: client dropped
  unsigned long long ignored = 0;     // requests not answered (plant silent)
};

class ModbusTcpServer {
 public:
  using Clock = std::chrono::steady_clock;
  // What a request may write: false for a read-only register (the reply is
  // an ILLEGAL DATA ADDRESS exception and nothing is written).
  using WritableCheck = std::function<bool(int address)>;
  // After a read whose requests were answered: wall milliseconds from the
  // arrival of the newest of them (the kernel's receive time of the bytes
  // read; -1 when the kernel gave none) to the last answer sent, and how
  // many requests the read held.
  using AnswerObserver = std::function<void(double late_ms, int requests)>;

  // Throws std::runtime_error when the address cannot be bound.
  ModbusTcpServer(const TcpServerOptions& options, modbus_mapping_t* mapping, int unit_id, WritableCheck writable);
  ~ModbusTcpServer();
  ModbusTcpServer(const ModbusTcpServer&) = delete;
  ModbusTcpServer& operator=(const ModbusTcpServer&) = delete;

  int port() const { return port_; }
  std::string endpoint() const { return options_.host + ":" + std::to_string(port_); }

  // The descriptors to poll: appended to `fds` (listener first, then the
  // clients); pass the same range back to service().
  void append_pollfds(std::vector<pollfd>& fds) const;
  // Accepts, reads and answers what poll() reported. `after_write` runs
  // after each request that wrote registers (the plant takes the commands).
  void service(const pollfd* fds, std::size_t count, const std::function<void()>& after_write);
  // Drops clients past their request or idle timeout.
  void expire(Clock::time_point now);

  // A plant that has stopped answering: requests are read and discarded.
  void set_silent(bool silent) { silent_ = silent; }
  void set_answer_observer(AnswerObserver observer) { observer_ = std::move(observer); }
  std::size_t clients() const { return clients_.size(); }
  const TcpServerStats& stats() const { return stats_; }

 private:
  struct Client {
    int fd = -1;
    std::uint8_t buffer[MODBUS_TCP_MAX_ADU_LENGTH];
    std::size_t length = 0;
    Clock::time_point request_started;
    Clock::time_point last_activity;
  };

  void accept_all();
  // false: the client is to be closed.
  bool read_client(Client& client, const std::function<void()>& after_write);
  // read() with the kernel's receive time of the bytes (realtime ns; 0: none).
  long receive(int fd, std::uint8_t* into, std::size_t size, std::int64_t& arrived_ns) const;
  bool answer(Client& client, std::size_t frame_length, const std::function<void()>& after_write);
  bool request_writes_read_only(const std::uint8_t* pdu, std::size_t length) const;
  void close_client(std::size_t index);

  TcpServerOptions options_;
  modbus_mapping_t* mapping_;
  int unit_id_;
  WritableCheck writable_;
  AnswerObserver observer_;
  modbus_t* context_ = nullptr;
  int listen_fd_ = -1;
  int port_ = 0;
  bool silent_ = false;
  std::vector<Client> clients_;
  TcpServerStats stats_;
};

}  // namespace glider::plant
