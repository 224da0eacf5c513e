// SPDX-License-Identifier: Apache-2.0
#pragma once
// The LZ4 forms of the Slocum files (.dcd, .scd, .ccc; docs/slocum-binary.md,
// "Writing"), as a sink in front of another: the names get the compressed
// extension and every write becomes LZ4 blocks framed by their big-endian
// 16-bit size, the glider's form (blocks of at most 32 KiB of data). Each of
// the writer's buffers is one block written at once, so a file cut by a
// power loss ends on a block boundary and its blocks read. Liblz4's block
// API with its state on the stack: no allocation.
#include <array>
#include <cstddef>

#include "glider/firmware/log/slocum_sink.hpp"

namespace glider::fw {

class SlocumLz4Sink final : public SlocumSink {
 public:
  static constexpr std::size_t kBlockBytes = std::size_t{32} * 1024;

  explicit SlocumLz4Sink(SlocumSink& inner) : inner_(inner) {}

  bool open(int slot, const char* name) override;
  bool write(int slot, const char* data, std::size_t size) override;
  bool close(int slot) override { return inner_.close(slot); }

 private:
  SlocumSink& inner_;
  std::array<char, 2 + kBlockBytes + kBlockBytes / 255 + 16> block_{};  // LZ4_COMPRESSBOUND(kBlockBytes)
  std::array<char, 256> name_{};
};

}  // namespace glider::fw
