// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where the Slocum writer's files go (docs/slocum-binary.md, "Writing"): a
// few numbered file slots, each opened by name, written in whole buffers and
// closed durably. The SIL gives it a local directory, glider-firmware its log
// directory (SlocumDirectorySink); tests give it memory or a sink that stops
// (a power cut). Calls must not allocate; each returns false on failure and
// the writer counts what was lost.
#include <cstddef>

namespace glider::fw {

class SlocumSink {
 public:
  static constexpr int kSlots = 4;  // the .dbd, the .sbd, and a cache file at start-up

  virtual ~SlocumSink() = default;
  // Creates or truncates `name` (relative to the sink's place; "cac/x.cac"
  // names a file in its cac/ folder) in slot `slot` (0..kSlots-1).
  virtual bool open(int slot, const char* name) = 0;
  // Appends all of `data`, or nothing: a failed write leaves the file as it was.
  virtual bool write(int slot, const char* data, std::size_t size) = 0;
  // Makes the file durable (fsync) and closes it.
  virtual bool close(int slot) = 0;
};

}  // namespace glider::fw
