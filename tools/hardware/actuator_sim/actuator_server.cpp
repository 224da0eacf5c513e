// SPDX-License-Identifier: Apache-2.0
#include "actuator_server.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <modbus/modbus.h>
#include <poll.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "garbled_reply.hpp"
#include "glider/hal_linux/register_map.hpp"
#include "modbus_request.hpp"

namespace glider::sim_tools {
namespace {

namespace regs = hal_linux::regs;

double monotonic_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

int word_at(const std::uint8_t* p) { return (p[0] << 8) | p[1]; }

bool is_read_only(int offset) { return offset == regs::kIdent || offset == regs::kVersion || offset >= regs::kActual; }

}  // namespace

ActuatorServer::ActuatorServer(const ServerOptions& options) : options_(options), faults_(options.faults) {
  const hal_linux::ModbusBoard& board = options_.board;
  for (const hal_linux::AxisConfig* axis : {&board.pump, &board.slide}) {
    axes_.push_back({axis->slave, axis->base_address, SimulatedAxis(*axis, options_.faults.stall_after_s)});
  }
  for (const Axis& axis : axes_) {
    _modbus_mapping_t*& mapping = mappings_[axis.slave];
    if (mapping == nullptr) {
      int size = 0;
      for (const Axis& other : axes_) {
        if (other.slave == axis.slave) size = std::max(size, other.base + regs::kBlockLength);
      }
      mapping = modbus_mapping_new(0, 0, size, 0);
    }
  }
  const hal_linux::BusConfig& bus = board.bus;
  if (bus.transport == hal_linux::Transport::kTcp) {
    context_ = modbus_new_tcp(bus.host.c_str(), bus.port);
    if (context_ == nullptr) throw std::runtime_error("tcp " + bus.host + ": " + modbus_strerror(errno));
    listen_socket_ = modbus_tcp_listen(context_, 128);
    if (listen_socket_ == -1) throw std::runtime_error(hal_linux::describe(bus) + ": " + modbus_strerror(errno));
    sockaddr_in bound{};
    socklen_t size = sizeof bound;
    getsockname(listen_socket_, reinterpret_cast<sockaddr*>(&bound), &size);
    endpoint_ = "tcp " + bus.host + ":" + std::to_string(ntohs(bound.sin_port));
  } else {
    if (mappings_.size() != 1) {
      throw std::runtime_error("rtu: libmodbus' RTU server answers one slave id; give both axes the same slave");
    }
    context_ = modbus_new_rtu(bus.device.c_str(), bus.baud, bus.parity, bus.data_bits, bus.stop_bits);
    if (context_ == nullptr) throw std::runtime_error(hal_linux::describe(bus) + ": " + modbus_strerror(errno));
    modbus_set_slave(context_, mappings_.begin()->first);
    if (modbus_connect(context_) == -1) {
      throw std::runtime_error(hal_linux::describe(bus) + ": " + modbus_strerror(errno));
    }
    if (bus.rs485 && modbus_rtu_set_serial_mode(context_, MODBUS_RTU_RS485) == -1) {
      warning_ = "RS-485 mode not available (" + std::string(modbus_strerror(errno)) + "), serving anyway";
    }
    endpoint_ = hal_linux::describe(bus);
  }
  for (Axis& axis : axes_) axis.model.publish(mappings_[axis.slave]->tab_registers + axis.base);
  last_time_s_ = monotonic_s();
}

ActuatorServer::~ActuatorServer() {
  if (listen_socket_ != -1) close(listen_socket_);
  if (context_ != nullptr) {
    modbus_close(context_);
    modbus_free(context_);
  }
  for (auto& [slave, mapping] : mappings_) modbus_mapping_free(mapping);
}

void ActuatorServer::run(const volatile std::sig_atomic_t& stop) {
  if (listen_socket_ != -1) {
    serve_tcp(stop);
  } else {
    serve_rtu(stop);
  }
}

void ActuatorServer::advance() {
  const double now = monotonic_s();
  const double dt = (now - last_time_s_) * options_.time_scale;
  last_time_s_ = now;
  // Small steps so a limit or the target is not overshot by a long gap.
  const int steps = std::max(1, static_cast<int>(dt / 0.05));
  for (Axis& axis : axes_) {
    for (int i = 0; i < steps; ++i) axis.model.step(dt / steps);
    axis.model.publish(mappings_[axis.slave]->tab_registers + axis.base);
  }
}

bool ActuatorServer::writes_read_only(int slave, int address, int count) const {
  for (const Axis& axis : axes_) {
    if (axis.slave != slave) continue;
    for (int a = address; a < address + count; ++a) {
      const int offset = a - axis.base;
      if (offset >= 0 && offset < regs::kBlockLength && is_read_only(offset)) return true;
    }
  }
  return false;
}

void ActuatorServer::handle(const std::uint8_t* query, int length) {
  const int header = modbus_get_header_length(context_);
  const int slave = query[header - 1];
  const int function = query[header];
  const auto found = mappings_.find(slave);
  if (found == mappings_.end()) return;  // nobody with that id on this bus
  modbus_mapping_t* mapping = found->second;
  advance();
  const ReplyAction action = faults_.next();
  if (faults_.delay_ms() > 0) std::this_thread::sleep_for(std::chrono::milliseconds(faults_.delay_ms()));
  const bool is_write = function == MODBUS_FC_WRITE_SINGLE_REGISTER || function == MODBUS_FC_WRITE_MULTIPLE_REGISTERS;
  const int count = function == MODBUS_FC_WRITE_MULTIPLE_REGISTERS ? word_at(query + header + 3) : 1;
  switch (action) {
    case ReplyAction::kSilent:
      return;
    case ReplyAction::kException:
      modbus_reply_exception(context_, query, MODBUS_EXCEPTION_SLAVE_OR_SERVER_FAILURE);
      return;
    case ReplyAction::kGarbled: {
      const auto frame =
          garbled_reply(query, header, listen_socket_ == -1, mapping->tab_registers, mapping->nb_registers);
      if (write(modbus_get_socket(context_), frame.data(), frame.size()) < 0) return;
      return;
    }
    case ReplyAction::kReply:
      break;
  }
  if (is_write && writes_read_only(slave, word_at(query + header + 1), count)) {
    modbus_reply_exception(context_, query, MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS);
    return;
  }
  modbus_reply(context_, query, length, mapping);
  if (is_write) {
    for (Axis& axis : axes_) {
      if (axis.slave != slave) continue;
      axis.model.take_commands(mapping->tab_registers + axis.base);
      axis.model.publish(mapping->tab_registers + axis.base);
    }
  }
}

void ActuatorServer::serve_frame(int fd, const std::uint8_t* frame, std::size_t length) {
  // Checked here, not by libmodbus: its answer to an oversize read sleeps and
  // flushes the socket, which stalled every client and ate the next request.
  const int exception = request_exception(frame, length);
  if (exception != 0) {
    ++stats_.exceptions;
    const std::vector<std::uint8_t> reply = exception_reply(frame, exception);
    if (send(fd, reply.data(), reply.size(), MSG_NOSIGNAL) < 0) return;  // the client is gone: poll says so next
    return;
  }
  ++stats_.requests;
  modbus_set_socket(context_, fd);
  handle(frame, static_cast<int>(length));
}

namespace {

struct Client {
  int fd;
  std::vector<std::uint8_t> pending;  // bytes of a frame not yet whole
  double last_byte_s;
  double frame_started_s;
};

}  // namespace

void ActuatorServer::serve_tcp(const volatile std::sig_atomic_t& stop) {
  // poll(), not select(): no FD_SETSIZE limit; every socket non-blocking and
  // every frame assembled here, so no client can make the loop wait for it.
  fcntl(listen_socket_, F_SETFL, fcntl(listen_socket_, F_GETFL) | O_NONBLOCK);
  std::vector<Client> clients;
  std::vector<pollfd> polled;
  std::uint8_t chunk[kMaxTcpFrameLength];
  while (stop == 0) {
    polled.assign(1, pollfd{listen_socket_, POLLIN, 0});
    for (const Client& c : clients) polled.push_back({c.fd, POLLIN, 0});
    const int ready = poll(polled.data(), polled.size(), 50);  // 50 ms: the idle dynamics step and the stop check
    const double now = monotonic_s();
    if (ready <= 0) advance();
    for (std::size_t i = 1; i < polled.size(); ++i) {
      Client& c = clients[i - 1];
      if ((polled[i].revents & (POLLIN | POLLHUP | POLLERR)) == 0) continue;
      const ssize_t got = recv(c.fd, chunk, sizeof chunk, 0);
      if (got <= 0) {
        if (got < 0 && (errno == EAGAIN || errno == EINTR)) continue;
        close(c.fd);
        c.fd = -1;
        continue;
      }
      if (c.pending.empty()) c.frame_started_s = now;
      c.last_byte_s = now;
      c.pending.insert(c.pending.end(), chunk, chunk + got);
      // Every whole frame in the buffer, in order; a malformed header drops the client.
      std::size_t used = 0;
      while (c.fd != -1) {
        const std::size_t size = tcp_frame_size(c.pending.data() + used, c.pending.size() - used);
        if (size == kFrameIncomplete) break;
        if (size == kFrameMalformed) {
          ++stats_.malformed;
          close(c.fd);
          c.fd = -1;
          break;
        }
        serve_frame(c.fd, c.pending.data() + used, size);
        used += size;
        c.frame_started_s = now;
      }
      if (c.fd != -1) c.pending.erase(c.pending.begin(), c.pending.begin() + static_cast<std::ptrdiff_t>(used));
    }
    for (Client& c : clients) {
      const bool frame_late = !c.pending.empty() && now - c.frame_started_s > options_.frame_timeout_s;
      if (c.fd != -1 && (frame_late || now - c.last_byte_s > options_.idle_timeout_s)) {
        ++stats_.timed_out;
        close(c.fd);
        c.fd = -1;
      }
    }
    clients.erase(std::remove_if(clients.begin(), clients.end(), [](const Client& c) { return c.fd == -1; }),
                  clients.end());
    if ((polled[0].revents & POLLIN) != 0) {
      // Everything waiting, bounded: a flood of connections cannot starve the clients.
      for (int n = 0; n < 256; ++n) {
        const int fd = accept4(listen_socket_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
        if (fd == -1) break;
        if (static_cast<int>(clients.size()) >= options_.max_clients) {
          ++stats_.refused;
          if (stats_.refused == 1 || stats_.refused % 1000 == 0) {
            std::fprintf(stderr, "glider-actuator-sim: connection refused: %d clients already (the cap); %llu so far\n",
                         options_.max_clients, static_cast<unsigned long long>(stats_.refused));
          }
          close(fd);
          continue;
        }
        ++stats_.accepted;
        clients.push_back({fd, {}, now, now});
      }
    }
  }
  for (const Client& c : clients) close(c.fd);
  modbus_set_socket(context_, -1);
}

void ActuatorServer::serve_rtu(const volatile std::sig_atomic_t& stop) {
  std::uint8_t query[MODBUS_RTU_MAX_ADU_LENGTH];
  const int fd = modbus_get_socket(context_);
  while (stop == 0) {
    fd_set readable;
    FD_ZERO(&readable);
    FD_SET(fd, &readable);
    timeval tick{0, 50'000};
    if (select(fd + 1, &readable, nullptr, nullptr, &tick) <= 0) {
      advance();
      continue;
    }
    const int length = modbus_receive(context_, query);
    if (length > 0) {
      handle(query, length);
    } else if (length == -1) {
      modbus_flush(context_);  // bad CRC or a partial frame: resynchronise
      if (errno == EIO || errno == EBADF) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
}

}  // namespace glider::sim_tools
