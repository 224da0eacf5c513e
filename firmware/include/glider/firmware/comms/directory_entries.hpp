// SPDX-License-Identifier: Apache-2.0
#pragma once
// A folder's entries without the heap: getdents64 into a fixed buffer on the
// stack (opendir mallocs a 32 KiB buffer of its own). Used where a folder is
// read in flight: the `send` listing (zmodem_transfer.cpp) and an upload's
// install (mission_reload.cpp).
#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cstring>

namespace glider::fw::comms {

// Calls visit(dir_fd, name, d_type) for every entry but "." and ".." (d_type
// may be DT_UNKNOWN: fstatat(dir_fd, name) then tells); visit returns false
// to stop. False when the folder cannot be opened.
template <typename Visit>
bool for_each_directory_entry(const char* path, Visit&& visit) {
  const int dir = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return false;
  struct Closer {  // closed also when visit throws (an install's copy)
    int fd;
    ~Closer() { ::close(fd); }
  } closer{dir};
  alignas(8) std::array<char, 4096> buffer{};
  bool more = true;
  while (more) {
    const ssize_t got = ::getdents64(dir, buffer.data(), buffer.size());
    if (got <= 0) break;
    for (ssize_t at = 0; at < got && more;) {
      const auto* entry = reinterpret_cast<const dirent64*>(buffer.data() + at);
      at += entry->d_reclen;
      const char* name = entry->d_name;
      if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0) continue;
      more = visit(dir, name, entry->d_type);
    }
  }
  return true;
}

}  // namespace glider::fw::comms
