// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace glider::fw::comms {

// The glider's file store as a transfer sees it: one file open at a time,
// read or written sequentially from a chosen offset, and an atomic rename so
// that a file received under a temporary name appears under its real name
// only when it is complete. Names are plain file names (no directories): the
// implementation decides which folder they live in.
class FileAccess {
 public:
  enum class Mode : std::uint8_t {
    read,    // existing file, from offset 0 (seek to move)
    create,  // new empty file (an existing one is truncated)
    append,  // existing file kept, writes go to its end
  };
  virtual ~FileAccess() = default;
  // Size in bytes of the named file, or -1 if there is none.
  virtual std::int64_t size(std::string_view name) = 0;
  // Modification time, seconds since 1970 (0 if unknown).
  virtual std::int64_t mtime(std::string_view name) = 0;
  virtual bool open(std::string_view name, Mode mode) = 0;
  virtual bool seek(std::int64_t offset) = 0;
  // Bytes read into out (0 at the end of the file or on an error).
  virtual std::size_t read(std::span<std::uint8_t> out) = 0;
  virtual bool write(std::span<const std::uint8_t> data) = 0;
  // Flushes and closes the open file (true if everything reached the store).
  virtual bool close() = 0;
  // Replaces `to` (if present) with `from` in one step.
  virtual bool rename(std::string_view from, std::string_view to) = 0;
  virtual bool remove(std::string_view name) = 0;
};

}  // namespace glider::fw::comms
