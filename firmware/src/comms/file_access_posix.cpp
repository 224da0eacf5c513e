// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/comms/file_access_posix.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

namespace glider::fw::comms {

PosixFileAccess::PosixFileAccess(std::string directory) : directory_(std::move(directory)) {}

PosixFileAccess::~PosixFileAccess() {
  if (fd_ >= 0) ::close(fd_);
}

const char* PosixFileAccess::path(std::string_view name, int which) {
  auto& buffer = path_buffer_[static_cast<std::size_t>(which)];
  const int n = std::snprintf(buffer.data(), buffer.size(), "%s/%.*s", directory_.c_str(),
                              static_cast<int>(name.size()), name.data());
  if (n < 0 || static_cast<std::size_t>(n) >= buffer.size()) return nullptr;
  return buffer.data();
}

std::int64_t PosixFileAccess::size(std::string_view name) {
  const char* p = path(name, 0);
  struct stat st {};
  if (p == nullptr || ::stat(p, &st) != 0 || !S_ISREG(st.st_mode)) return -1;
  return static_cast<std::int64_t>(st.st_size);
}

std::int64_t PosixFileAccess::mtime(std::string_view name) {
  const char* p = path(name, 0);
  struct stat st {};
  if (p == nullptr || ::stat(p, &st) != 0) return 0;
  return static_cast<std::int64_t>(st.st_mtime);
}

bool PosixFileAccess::open(std::string_view name, Mode mode) {
  if (fd_ >= 0) close();
  const char* p = path(name, 0);
  if (p == nullptr) return false;
  int flags = O_RDONLY;
  if (mode == Mode::create) flags = O_WRONLY | O_CREAT | O_TRUNC;
  if (mode == Mode::append) flags = O_WRONLY | O_CREAT | O_APPEND;
  fd_ = ::open(p, flags | O_CLOEXEC, 0644);
  return fd_ >= 0;
}

bool PosixFileAccess::seek(std::int64_t offset) {
  return fd_ >= 0 && ::lseek(fd_, static_cast<off_t>(offset), SEEK_SET) == static_cast<off_t>(offset);
}

std::size_t PosixFileAccess::read(std::span<std::uint8_t> out) {
  std::size_t done = 0;
  while (fd_ >= 0 && done < out.size()) {
    const ssize_t n = ::read(fd_, out.data() + done, out.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  return done;
}

bool PosixFileAccess::write(std::span<const std::uint8_t> data) {
  std::size_t done = 0;
  while (fd_ >= 0 && done < data.size()) {
    const ssize_t n = ::write(fd_, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return fd_ >= 0;
}

bool PosixFileAccess::close() {
  if (fd_ < 0) return false;
  const int mode = ::fcntl(fd_, F_GETFL);
  const bool synced = (mode & O_ACCMODE) == O_RDONLY || ::fsync(fd_) == 0;
  const bool closed = ::close(fd_) == 0;
  fd_ = -1;
  return synced && closed;
}

bool PosixFileAccess::rename(std::string_view from, std::string_view to) {
  const char* a = path(from, 0);
  const char* b = path(to, 1);
  return a != nullptr && b != nullptr && ::rename(a, b) == 0;
}

bool PosixFileAccess::remove(std::string_view name) {
  const char* p = path(name, 0);
  return p != nullptr && ::unlink(p) == 0;
}

}  // namespace glider::fw::comms
