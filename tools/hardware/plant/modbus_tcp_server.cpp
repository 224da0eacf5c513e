// SPDX-License-Identifier: Apache-2.0
#include "modbus_tcp_server.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <vector>

#include "modbus_request.hpp"

namespace glider::plant {
namespace {

constexpr std::size_t kMbapLength = sim_tools::kMbapHeaderLength;

int word_at(const std::uint8_t* p) { return (p[0] << 8) | p[1]; }

// The exception reply built here, not by libmodbus: modbus_reply_exception
// adds 0x80 to the function in a byte, so a request with function 0x99 was
// answered as function 0x19. exception_reply sets the bit (0x99 stays 0x99).
int send_exception(int fd, const std::uint8_t* frame, int code) {
  const std::vector<std::uint8_t> reply = sim_tools::exception_reply(frame, code);
  return static_cast<int>(send(fd, reply.data(), reply.size(), MSG_NOSIGNAL));
}

}  // namespace

ModbusTcpServer::ModbusTcpServer(const TcpServerOptions& options, modbus_mapping_t* mapping, int unit_id,
                                 WritableCheck writable)
    : options_(options), mapping_(mapping), unit_id_(unit_id), writable_(std::move(writable)) {
  context_ = modbus_new_tcp(options.host.c_str(), options.port);
  if (context_ == nullptr) throw std::runtime_error("modbus tcp " + options.host + ": " + modbus_strerror(errno));
  // libmodbus sleeps one response timeout before it flushes after some
  // exception replies (an oversize read): 1 us, or one bad client would
  // stall every other for half a second.
  modbus_set_response_timeout(context_, 0, 1);
  listen_fd_ = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (listen_fd_ < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
  const int yes = 1;
  setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  // Asked here, at start-up, too: the kernel switches its receive stamps on
  // a moment after the first socket asks (deferred), and keeps them on while
  // one asks, so the firmware's first requests are timed as well.
  setsockopt(listen_fd_, SOL_SOCKET, SO_TIMESTAMPNS, &yes, sizeof yes);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(options.port));
  if (inet_pton(AF_INET, options.host.c_str(), &address.sin_addr) != 1) {
    throw std::runtime_error("modbus tcp: " + options.host + " is not a numeric IPv4 address");
  }
  if (bind(listen_fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || listen(listen_fd_, 128) != 0) {
    throw std::runtime_error("modbus tcp " + endpoint() + ": " + std::strerror(errno));
  }
  socklen_t size = sizeof address;
  getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&address), &size);
  port_ = ntohs(address.sin_port);
  clients_.reserve(static_cast<std::size_t>(options.max_clients));
}

ModbusTcpServer::~ModbusTcpServer() {
  for (const Client& client : clients_) close(client.fd);
  if (listen_fd_ >= 0) close(listen_fd_);
  modbus_free(context_);
}

void ModbusTcpServer::append_pollfds(std::vector<pollfd>& fds) const {
  fds.push_back({listen_fd_, POLLIN, 0});
  for (const Client& client : clients_) fds.push_back({client.fd, POLLIN, 0});
}

void ModbusTcpServer::service(const pollfd* fds, std::size_t count, const std::function<void()>& after_write) {
  if (count == 0) return;
  // Clients first, from the back, so that closing one keeps the indices of
  // those not yet seen; new connections after (they are not in `fds`).
  for (std::size_t i = count - 1; i >= 1; --i) {
    const std::size_t index = i - 1;
    if (index >= clients_.size() || fds[i].fd != clients_[index].fd) continue;
    if ((fds[i].revents & (POLLIN | POLLHUP | POLLERR)) == 0) continue;
    if (!read_client(clients_[index], after_write)) close_client(index);
  }
  if ((fds[0].revents & POLLIN) != 0) accept_all();
}

void ModbusTcpServer::accept_all() {
  // Bounded: at most the listen backlog in one call.
  for (int k = 0; k < 128; ++k) {
    const int fd = accept4(listen_fd_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) return;
    if (clients_.size() >= static_cast<std::size_t>(options_.max_clients)) {
      ++stats_.refused;  // a clear refusal: the connection closes at once
      close(fd);
      continue;
    }
    const int yes = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
    // The kernel's receive time on each read: how long a request waited for
    // a plant that was not scheduled (its answer lateness). Where refused,
    // reads carry no time and the answers are counted untimed.
    setsockopt(fd, SOL_SOCKET, SO_TIMESTAMPNS, &yes, sizeof yes);
    Client& client = clients_.emplace_back();
    client.fd = fd;
    client.last_activity = Clock::now();
    ++stats_.accepted;
  }
}

long ModbusTcpServer::receive(int fd, std::uint8_t* into, std::size_t size, std::int64_t& arrived_ns) const {
  iovec data{into, size};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(timespec))];
  msghdr message{};
  message.msg_iov = &data;
  message.msg_iovlen = 1;
  message.msg_control = control;
  message.msg_controllen = sizeof control;
  const ssize_t n = recvmsg(fd, &message, 0);
  arrived_ns = 0;
  for (cmsghdr* c = CMSG_FIRSTHDR(&message); n > 0 && c != nullptr; c = CMSG_NXTHDR(&message, c)) {
    if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_TIMESTAMPNS) {
      timespec at{};
      std::memcpy(&at, CMSG_DATA(c), sizeof at);
      arrived_ns = static_cast<std::int64_t>(at.tv_sec) * 1'000'000'000 + at.tv_nsec;
    }
  }
  return static_cast<long>(n);
}

bool ModbusTcpServer::read_client(Client& client, const std::function<void()>& after_write) {
  std::int64_t arrived_ns = 0;
  const long n = receive(client.fd, client.buffer + client.length, sizeof client.buffer - client.length, arrived_ns);
  if (n == 0) return false;  // the client closed
  if (n < 0) return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR;
  const auto now = Clock::now();
  if (client.length == 0) client.request_started = now;
  client.last_activity = now;
  client.length += static_cast<std::size_t>(n);
  // Every whole request in the buffer, in order (a client may pipeline).
  int answered = 0;
  while (true) {
    const std::size_t frame = sim_tools::tcp_frame_size(client.buffer, client.length);
    if (frame == sim_tools::kFrameMalformed) {
      ++stats_.malformed;  // the stream cannot be resynchronised
      return false;
    }
    if (frame == sim_tools::kFrameIncomplete) break;
    if (!answer(client, frame, after_write)) return false;
    if (!silent_) ++answered;
    client.length -= frame;
    std::memmove(client.buffer, client.buffer + frame, client.length);
    client.request_started = now;
  }
  if (answered > 0 && observer_) {
    double late_ms = -1.0;
    if (arrived_ns > 0) {
      timespec sent{};
      clock_gettime(CLOCK_REALTIME, &sent);
      const std::int64_t sent_ns = static_cast<std::int64_t>(sent.tv_sec) * 1'000'000'000 + sent.tv_nsec;
      late_ms = static_cast<double>(std::max<std::int64_t>(0, sent_ns - arrived_ns)) / 1e6;
    }
    observer_(late_ms, answered);
  }
  return true;
}

bool ModbusTcpServer::request_writes_read_only(const std::uint8_t* pdu, std::size_t length) const {
  const int function = pdu[0];
  int address = 0;
  int count = 0;
  if (function == MODBUS_FC_WRITE_SINGLE_REGISTER && length >= 5) {
    address = word_at(pdu + 1);
    count = 1;
  } else if (function == MODBUS_FC_WRITE_MULTIPLE_REGISTERS && length >= 5) {
    address = word_at(pdu + 1);
    count = word_at(pdu + 3);
  } else {
    return false;  // not a register write
  }
  for (int a = address; a < address + count; ++a) {
    if (!writable_(a)) return true;
  }
  return false;
}

bool ModbusTcpServer::answer(Client& client, std::size_t frame_length, const std::function<void()>& after_write) {
  ++stats_.requests;
  if (silent_) {
    ++stats_.ignored;
    return true;
  }
  const std::uint8_t* frame = client.buffer;
  const std::uint8_t* pdu = frame + kMbapLength;
  const std::size_t pdu_length = frame_length - kMbapLength;
  modbus_set_socket(context_, client.fd);
  int sent = 0;
  if (frame[6] != unit_id_ && frame[6] != 0xFF) {
    ++stats_.exceptions;
    sent = send_exception(client.fd, frame, MODBUS_EXCEPTION_GATEWAY_TARGET);
  } else if (const int code = sim_tools::request_exception(frame, frame_length); code != 0) {
    ++stats_.exceptions;  // a function, quantity or byte count the register map does not serve
    sent = send_exception(client.fd, frame, code);
  } else if (request_writes_read_only(pdu, pdu_length)) {
    ++stats_.exceptions;
    sent = send_exception(client.fd, frame, MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS);
  } else {
    sent = modbus_reply(context_, frame, static_cast<int>(frame_length), mapping_);
    const int function = pdu[0];
    if (function == MODBUS_FC_WRITE_SINGLE_REGISTER || function == MODBUS_FC_WRITE_MULTIPLE_REGISTERS) {
      after_write();
    }
  }
  return sent > 0;  // a client that cannot take its reply is dropped
}

void ModbusTcpServer::expire(Clock::time_point now) {
  const auto request_limit = std::chrono::milliseconds(options_.request_timeout_ms);
  const auto idle_limit = std::chrono::milliseconds(options_.idle_timeout_ms);
  for (std::size_t i = clients_.size(); i-- > 0;) {
    const Client& c = clients_[i];
    if ((c.length > 0 && now - c.request_started > request_limit) || now - c.last_activity > idle_limit) {
      ++stats_.timed_out;
      close_client(i);
    }
  }
}

void ModbusTcpServer::close_client(std::size_t index) {
  close(clients_[index].fd);
  clients_[index] = clients_.back();  // order does not matter between clients
  clients_.pop_back();
}

}  // namespace glider::plant
