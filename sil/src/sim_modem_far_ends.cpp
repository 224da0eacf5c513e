// SPDX-License-Identifier: Apache-2.0
// The far ends of the simulated modem's calls: the tests' in-process shore
// and a real shore station over loopback TCP.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "glider/sil/sim_modem.hpp"

namespace glider::sil {

bool FakeShore::answer(const std::string& number, double now_s) {
  numbers_.push_back(number);
  if (!listening || std::find(dead_numbers.begin(), dead_numbers.end(), number) != dead_numbers.end()) return false;
  ++calls_;
  connected_ = true;
  connect_s_ = now_s;
  next_ = 0;
  pending_.clear();
  return true;
}

void FakeShore::receive(std::span<const std::uint8_t> bytes, double) {
  transcript_.append(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

std::vector<std::uint8_t> FakeShore::take(std::size_t max, double now_s) {
  while (connected_ && next_ < script.size() && now_s - connect_s_ >= script[next_].after_connect_s) {
    pending_.insert(pending_.end(), script[next_].text.begin(), script[next_].text.end());
    ++next_;
  }
  const std::size_t n = std::min(max, pending_.size());
  std::vector<std::uint8_t> out(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(n));
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(n));
  return out;
}

void FakeShore::hangup(double) {
  if (connected_) ++hangups_;
  connected_ = false;
}

TcpShore::TcpShore(std::string host, int port, int answer_wait_ms)
    : host_(std::move(host)), port_(port), answer_wait_ms_(answer_wait_ms) {}

TcpShore::~TcpShore() {
  if (fd_ >= 0) ::close(fd_);
}

bool TcpShore::answer(const std::string&, double) {
  hangup(0.0);
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const std::string port = std::to_string(port_);
  if (::getaddrinfo(host_.c_str(), port.c_str(), &hints, &found) != 0 || found == nullptr) {
    error_ = "cannot resolve " + host_;
    return false;
  }
  fd_ = ::socket(found->ai_family, found->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  bool ok = fd_ >= 0;
  if (ok && ::connect(fd_, found->ai_addr, found->ai_addrlen) != 0) {
    ok = errno == EINPROGRESS;
    if (ok) {
      // Call set-up: wait at most 2 s for the shore to accept.
      pollfd p{fd_, POLLOUT, 0};
      int error = 0;
      socklen_t length = sizeof error;
      ok = ::poll(&p, 1, 2000) == 1 && ::getsockopt(fd_, SOL_SOCKET, SO_ERROR, &error, &length) == 0 && error == 0;
    }
  }
  ::freeaddrinfo(found);
  if (!ok) {
    error_ = "shore " + host_ + ":" + port + " not listening";
    hangup(0.0);
  }
  return ok;
}

void TcpShore::receive(std::span<const std::uint8_t> bytes, double) {
  std::size_t sent = 0;
  while (fd_ >= 0 && sent < bytes.size()) {
    const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
    } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      pollfd p{fd_, POLLOUT, 0};
      if (::poll(&p, 1, answer_wait_ms_) != 1) break;  // the shore is not reading: the rest is lost
    } else {
      break;
    }
  }
  if (sent > 0) answer_due_ = true;
}

std::vector<std::uint8_t> TcpShore::take(std::size_t max, double) {
  std::vector<std::uint8_t> out;
  if (fd_ < 0 || max == 0) return out;
  pollfd p{fd_, POLLIN, 0};
  if (::poll(&p, 1, 0) == 1) {
    out.resize(max);
    const ssize_t n = ::recv(fd_, out.data(), max, MSG_DONTWAIT);
    out.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  }
  shore_was_talking_ = !out.empty();
  if (!out.empty()) answer_due_ = false;
  return out;
}

void TcpShore::settle() {
  if (fd_ < 0 || !(answer_due_ || shore_was_talking_)) return;
  // Bytes already there, or the shore's next within the bound (not taken
  // here: the link's rate decides when they reach the glider).
  ++waits_;
  pollfd p{fd_, POLLIN, 0};
  if (::poll(&p, 1, answer_wait_ms_) != 1) ++unanswered_waits_;
  answer_due_ = false;  // answered, or it had its chance
  shore_was_talking_ = false;
}

void TcpShore::hangup(double) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  answer_due_ = shore_was_talking_ = false;
}

bool parse_shore_address(const std::string& text, std::string& host, int& port, std::string& error) {
  const std::size_t colon = text.rfind(':');
  host = colon == std::string::npos ? text : text.substr(0, colon);
  if (host.empty()) host = "127.0.0.1";
  port = kDefaultShorePort;
  if (colon == std::string::npos) return true;
  const std::string digits = text.substr(colon + 1);
  char* end = nullptr;
  const long value = std::strtol(digits.c_str(), &end, 10);
  if (digits.empty() || *end != '\0' || value < 1 || value > 65535) {
    error = "port value " + digits + " is outside the allowed range [1, 65535]";
    return false;
  }
  port = static_cast<int>(value);
  return true;
}

}  // namespace glider::sil
