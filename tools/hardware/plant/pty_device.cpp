// SPDX-License-Identifier: Apache-2.0
#include "pty_device.hpp"

#include <fcntl.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace glider::plant {
namespace {

// What the plant lets queue on a line: under the 4 KiB the tty's input
// buffer holds on Linux, so a whole sentence is never cut by the kernel.
constexpr int kLineRoom = 3072;

[[noreturn]] void fail(const std::string& link, const char* what) {
  throw std::runtime_error(link + ": " + what + ": " + std::strerror(errno));
}

}  // namespace

PtyDevice::PtyDevice(const std::string& link) : link_(link) {
  master_ = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (master_ < 0) fail(link, "posix_openpt");
  if (grantpt(master_) != 0 || unlockpt(master_) != 0) fail(link, "grantpt/unlockpt");
  char name[128];
  if (ptsname_r(master_, name, sizeof name) != 0) fail(link, "ptsname");
  slave_path_ = name;
  slave_keepalive_ = ::open(name, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (slave_keepalive_ < 0) fail(link, "open pty slave");
  termios tio{};
  if (tcgetattr(slave_keepalive_, &tio) != 0) fail(link, "tcgetattr");
  cfmakeraw(&tio);  // no echo, no line discipline: bytes as on a UART
  if (tcsetattr(slave_keepalive_, TCSANOW, &tio) != 0) fail(link, "tcsetattr");
  ::unlink(link.c_str());
  if (::symlink(name, link.c_str()) != 0) fail(link, "symlink");
}

PtyDevice::~PtyDevice() {
  ::unlink(link_.c_str());
  if (slave_keepalive_ >= 0) ::close(slave_keepalive_);
  if (master_ >= 0) ::close(master_);
}

std::size_t PtyDevice::write_some(const char* data, std::size_t size) {
  int queued = 0;
  if (ioctl(slave_keepalive_, TIOCINQ, &queued) != 0) return 0;
  const std::size_t room = queued < kLineRoom ? static_cast<std::size_t>(kLineRoom - queued) : 0;
  const ssize_t n = ::write(master_, data, std::min(room, size));
  return n > 0 ? static_cast<std::size_t>(n) : 0;
}

bool PtyDevice::write_all_or_drop(const std::string& bytes) {
  int queued = 0;
  // Room for the whole sentence in the line's buffer (4 KiB on Linux), or drop it.
  if (ioctl(slave_keepalive_, TIOCINQ, &queued) == 0 && queued + static_cast<int>(bytes.size()) > kLineRoom) {
    dropped_ += bytes.size();
    return false;
  }
  const ssize_t n = ::write(master_, bytes.data(), bytes.size());
  if (n != static_cast<ssize_t>(bytes.size())) {
    dropped_ += bytes.size() - (n > 0 ? static_cast<std::size_t>(n) : 0);
    return false;
  }
  return true;
}

bool PtyDevice::write_newest(const std::string& bytes) {
  int queued = 0;
  if (ioctl(slave_keepalive_, TIOCINQ, &queued) == 0 && queued + static_cast<int>(bytes.size()) > kLineRoom &&
      tcflush(slave_keepalive_, TCIFLUSH) == 0) {
    discarded_ += static_cast<unsigned long long>(queued);
  }
  return write_all_or_drop(bytes);
}

}  // namespace glider::plant
