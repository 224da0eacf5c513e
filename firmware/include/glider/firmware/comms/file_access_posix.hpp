// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>
#include <climits>
#include <string>

#include "glider/firmware/comms/file_access.hpp"

namespace glider::fw::comms {

// FileAccess on one POSIX directory (the glider's transfer folder). Paths are
// built in a fixed buffer: no allocation after construction. close() fsyncs,
// so a file renamed after it is on the medium, not only in the page cache.
class PosixFileAccess : public FileAccess {
 public:
  explicit PosixFileAccess(std::string directory);
  ~PosixFileAccess() override;
  PosixFileAccess(const PosixFileAccess&) = delete;
  PosixFileAccess& operator=(const PosixFileAccess&) = delete;

  std::int64_t size(std::string_view name) override;
  std::int64_t mtime(std::string_view name) override;
  bool open(std::string_view name, Mode mode) override;
  bool seek(std::int64_t offset) override;
  std::size_t read(std::span<std::uint8_t> out) override;
  bool write(std::span<const std::uint8_t> data) override;
  bool close() override;
  bool rename(std::string_view from, std::string_view to) override;
  bool remove(std::string_view name) override;

 private:
  // The full path of name in path_buffer (index 0 or 1); nullptr if too long.
  const char* path(std::string_view name, int which);

  std::string directory_;
  std::array<std::array<char, PATH_MAX>, 2> path_buffer_{};
  int fd_ = -1;
};

}  // namespace glider::fw::comms
