// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/serial_port.hpp"

#include <fcntl.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <stdexcept>

namespace glider::hal_linux {
namespace {

std::optional<speed_t> speed_of(int baud) {
  switch (baud) {
    case 300:
      return B300;
    case 1200:
      return B1200;
    case 2400:
      return B2400;
    case 4800:
      return B4800;
    case 9600:
      return B9600;
    case 19200:
      return B19200;
    case 38400:
      return B38400;
    case 57600:
      return B57600;
    case 115200:
      return B115200;
    case 230400:
      return B230400;
    case 460800:
      return B460800;
    case 921600:
      return B921600;
    case 1000000:
      return B1000000;
    case 2000000:
      return B2000000;
    case 4000000:
      return B4000000;
    default:
      return std::nullopt;
  }
}

[[noreturn]] void fail(const std::string& device, const std::string& what) {
  throw std::runtime_error(device + ": " + what + ": " + std::strerror(errno));
}

}  // namespace

bool supported_baud(int baud) { return speed_of(baud).has_value(); }

std::unique_ptr<SerialPort> SerialPort::open(const std::string& device, int baud) {
  const auto speed = speed_of(baud);
  if (!speed) throw std::runtime_error(device + ": unsupported baud rate " + std::to_string(baud));
  const int fd = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) fail(device, "cannot open");
  termios tio{};
  if (::tcgetattr(fd, &tio) != 0) {
    const int saved = errno;
    ::close(fd);
    errno = saved;
    fail(device, "not a serial port (tcgetattr)");
  }
  ::cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~(CSTOPB | PARENB | CRTSCTS);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  ::cfsetispeed(&tio, *speed);
  ::cfsetospeed(&tio, *speed);
  if (::tcsetattr(fd, TCSANOW, &tio) != 0) {
    const int saved = errno;
    ::close(fd);
    errno = saved;
    fail(device, "cannot configure (tcsetattr)");
  }
  ::tcflush(fd, TCIFLUSH);  // whatever queued before start-up is old
  return std::unique_ptr<SerialPort>(new SerialPort(fd, device));
}

SerialPort::~SerialPort() { ::close(fd_); }

long SerialPort::read_some(char* buffer, std::size_t size) noexcept {
  const ssize_t n = ::read(fd_, buffer, size);
  if (n > 0) {
    stats_.bytes += static_cast<std::uint64_t>(n);
    return n;
  }
  if (n == 0 || errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return 0;
  ++stats_.errors;
  return -1;
}

long SerialPort::write_some(const char* bytes, std::size_t size) noexcept {
  const ssize_t n = ::write(fd_, bytes, size);
  if (n >= 0) return n;
  if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return 0;
  ++stats_.errors;
  return -1;
}

int SerialPort::carrier_detect() const noexcept {
  int lines = 0;
  if (::ioctl(fd_, TIOCMGET, &lines) != 0) return -1;
  return (lines & TIOCM_CD) != 0 ? 1 : 0;
}

}  // namespace glider::hal_linux
