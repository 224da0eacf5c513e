// SPDX-License-Identifier: Apache-2.0
#include "modem_bridge.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <stdexcept>

namespace glider::plant {
namespace {
constexpr double kGuardSimS = 1.0;  // Hayes S12: a second of silence either side of "+++"
constexpr std::size_t kMaxPendingDown = 16384;
}  // namespace

ModemBridge::ModemBridge(const std::string& link, const std::string& shore_host, int shore_port, double time_scale)
    : line_(std::make_unique<PtyDevice>(link)),
      host_(shore_host),
      port_(shore_port),
      guard_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kGuardSimS / time_scale))) {}

ModemBridge::~ModemBridge() {
  if (socket_ >= 0) ::close(socket_);
}

void ModemBridge::append_pollfds(std::vector<pollfd>& fds) const {
  fds.push_back({line_->master_fd(), POLLIN, 0});
  // The shore is read only while the line keeps up (back-pressure, as a modem's flow control).
  const bool take = socket_ >= 0 && pending_down_.size() < kMaxPendingDown;
  fds.push_back({take ? socket_ : -1, POLLIN, 0});  // fd -1: ignored by poll
}

void ModemBridge::service(const pollfd* fds, std::size_t count) {
  if (count >= 1 && (fds[0].revents & POLLIN) != 0) {
    std::uint8_t buffer[4096];
    const ssize_t n = ::read(line_->master_fd(), buffer, sizeof buffer);
    if (n > 0) from_glider(buffer, static_cast<std::size_t>(n));
  }
  if (count >= 2 && socket_ >= 0 && fds[1].fd == socket_ && (fds[1].revents & (POLLIN | POLLHUP | POLLERR)) != 0)
    from_shore();
  if (!pending_down_.empty()) {
    const std::size_t n = line_->write_some(pending_down_.data(), pending_down_.size());
    pending_down_.erase(0, n);
  }
  if (!pending_up_.empty() && socket_ >= 0) {
    const std::string rest = std::move(pending_up_);
    pending_up_.clear();
    to_shore(reinterpret_cast<const std::uint8_t*>(rest.data()), rest.size());
  }
  // "+++" followed by a guard time of silence: command mode, the call still up.
  if (escape_pending_ && Clock::now() - escape_at_ >= guard_) {
    escape_pending_ = false;
    data_mode_ = false;
    reply("OK");
  }
}

void ModemBridge::from_glider(const std::uint8_t* data, std::size_t n) {
  if (data_mode_) {
    const Clock::time_point now = Clock::now();
    if (n == 3 && data[0] == '+' && data[1] == '+' && data[2] == '+' && now - last_data_ >= guard_) {
      escape_pending_ = true;
      escape_at_ = now;
      return;
    }
    if (escape_pending_) {  // data within the guard: the "+++" was data
      escape_pending_ = false;
      static constexpr std::uint8_t kPlus[] = {'+', '+', '+'};
      to_shore(kPlus, 3);
    }
    last_data_ = now;
    to_shore(data, n);
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const char c = static_cast<char>(data[i]);
    if (echo_) to_glider(std::string(1, c));
    if (c == '\r') {
      const std::string line = line_buffer_;
      line_buffer_.clear();
      command(line);
    } else if (c != '\n' && line_buffer_.size() < 256) {
      line_buffer_.push_back(c);
    }
  }
}

void ModemBridge::command(const std::string& raw) {
  std::string line = raw;
  std::transform(line.begin(), line.end(), line.begin(), [](unsigned char c) { return std::toupper(c); });
  if (line == "AT") {
    reply("OK");
  } else if (line == "ATE0" || line == "ATE1") {
    echo_ = line == "ATE1";
    reply("OK");
  } else if (line == "AT+CSQ") {
    reply("+CSQ:5");  // the plant's sky is always clear; faults are SIL's (LinkModel)
    reply("OK");
  } else if (line.rfind("ATD", 0) == 0 && line.size() > 3) {
    ++stats_.calls;
    if (socket_ >= 0) hang_up(false);
    socket_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port_));
    const bool ok = socket_ >= 0 && ::inet_pton(AF_INET, host_.c_str(), &address.sin_addr) == 1 &&
                    ::connect(socket_, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
    if (!ok) {
      if (socket_ >= 0) ::close(socket_);
      socket_ = -1;
      reply("NO CARRIER");
      return;
    }
    const int one = 1;
    (void)::setsockopt(socket_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    (void)::fcntl(socket_, F_SETFL, ::fcntl(socket_, F_GETFL) | O_NONBLOCK);
    ++stats_.connects;
    data_mode_ = true;
    last_data_ = Clock::now();
    reply("CONNECT 19200");
  } else if (line == "ATH" || line == "ATH0") {
    hang_up(false);
    reply("OK");
  } else if (!line.empty()) {
    reply("ERROR");
  }
}

void ModemBridge::from_shore() {
  std::uint8_t buffer[4096];
  const ssize_t n = ::recv(socket_, buffer, sizeof buffer, 0);
  if (n > 0) {
    stats_.bytes_down += static_cast<std::uint64_t>(n);
    if (data_mode_) to_glider(std::string(reinterpret_cast<const char*>(buffer), static_cast<std::size_t>(n)));
    return;
  }
  if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return;
  hang_up(true);  // the shore hung up
}

void ModemBridge::to_shore(const std::uint8_t* data, std::size_t n) {
  if (socket_ < 0) return;
  std::size_t done = 0;
  if (pending_up_.empty()) {
    while (done < n) {
      const ssize_t w = ::send(socket_, data + done, n - done, MSG_NOSIGNAL);
      if (w <= 0) break;
      done += static_cast<std::size_t>(w);
    }
  }
  stats_.bytes_up += done;
  // What the socket did not take waits (a loopback socket rarely refuses).
  pending_up_.append(reinterpret_cast<const char*>(data) + done, n - done);
}

void ModemBridge::reply(const std::string& text) { to_glider("\r\n" + text + "\r\n"); }

void ModemBridge::to_glider(const std::string& bytes) {
  pending_down_ += bytes;
  const std::size_t n = line_->write_some(pending_down_.data(), pending_down_.size());
  pending_down_.erase(0, n);
}

void ModemBridge::hang_up(bool tell_glider) {
  if (socket_ >= 0) ::close(socket_);
  socket_ = -1;
  pending_up_.clear();
  escape_pending_ = false;
  const bool was_connected = data_mode_;
  data_mode_ = false;
  if (tell_glider && was_connected) reply("NO CARRIER");
}

}  // namespace glider::plant
