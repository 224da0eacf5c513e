// SPDX-License-Identifier: Apache-2.0
#pragma once
// Test doubles: an in-memory duplex link with seeded byte corruption and a
// carrier that can drop, and an in-memory file store.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "glider/firmware/comms/byte_stream.hpp"
#include "glider/firmware/comms/file_access.hpp"

namespace glider::test {

// One direction of the link: bounded (like a serial driver's buffer), with
// a per-byte corruption probability and an optional cut after N bytes.
struct Pipe {
  std::deque<std::uint8_t> bytes;
  std::size_t capacity = 4096;
  double corruption = 0.0;
  std::uint64_t carried = 0;
  std::uint64_t cut_after = UINT64_MAX;  // the carrier drops after this many bytes
  std::uint64_t corrupted = 0;
  std::mt19937_64* rng = nullptr;
};

class PipeEnd : public fw::comms::ByteStream {
 public:
  PipeEnd(Pipe& in, Pipe& out) : in_(in), out_(out) {}
  std::size_t read(std::span<std::uint8_t> out) override {
    std::size_t n = 0;
    while (n < out.size() && !in_.bytes.empty()) {
      out[n++] = in_.bytes.front();
      in_.bytes.pop_front();
    }
    return n;
  }
  std::size_t write(std::span<const std::uint8_t> data) override {
    std::size_t n = 0;
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::uniform_int_distribution<int> flip(1, 255);
    while (n < data.size() && out_.bytes.size() < out_.capacity) {
      std::uint8_t byte = data[n++];
      if (out_.carried++ >= out_.cut_after) continue;  // no carrier: the byte is lost
      if (out_.corruption > 0.0 && uniform(*out_.rng) < out_.corruption) {
        byte = static_cast<std::uint8_t>(byte ^ flip(*out_.rng));
        ++out_.corrupted;
      }
      out_.bytes.push_back(byte);
    }
    return n;
  }

 private:
  Pipe& in_;
  Pipe& out_;
};

class MemoryFiles : public fw::comms::FileAccess {
 public:
  std::map<std::string, std::vector<std::uint8_t>> files;
  std::map<std::string, std::int64_t> mtimes;
  bool fail_writes = false;

  std::int64_t size(std::string_view name) override {
    const auto it = files.find(std::string(name));
    return it == files.end() ? -1 : static_cast<std::int64_t>(it->second.size());
  }
  std::int64_t mtime(std::string_view name) override {
    const auto it = mtimes.find(std::string(name));
    return it == mtimes.end() ? 0 : it->second;
  }
  bool open(std::string_view name, Mode mode) override {
    open_ = std::string(name);
    position_ = 0;
    writing_ = false;
    if (mode == Mode::read) return files.count(open_) != 0;
    if (mode == Mode::create) files[open_].clear();
    files[open_];
    position_ = files[open_].size();
    writing_ = true;
    return true;
  }
  bool seek(std::int64_t offset) override {
    if (open_.empty() || offset < 0 || offset > static_cast<std::int64_t>(files[open_].size())) return false;
    position_ = static_cast<std::size_t>(offset);
    return true;
  }
  std::size_t read(std::span<std::uint8_t> out) override {
    const auto& data = files[open_];
    std::size_t n = 0;
    while (n < out.size() && position_ < data.size()) out[n++] = data[position_++];
    return n;
  }
  bool write(std::span<const std::uint8_t> data) override {
    if (fail_writes || !writing_) return false;
    auto& file = files[open_];
    file.insert(file.end(), data.begin(), data.end());
    return true;
  }
  bool close() override {
    open_.clear();
    writing_ = false;
    return true;
  }
  bool rename(std::string_view from, std::string_view to) override {
    const auto it = files.find(std::string(from));
    if (it == files.end()) return false;
    files[std::string(to)] = it->second;
    files.erase(std::string(from));
    return true;
  }
  bool remove(std::string_view name) override { return files.erase(std::string(name)) != 0; }

 private:
  std::string open_;
  std::size_t position_ = 0;
  bool writing_ = false;
};

}  // namespace glider::test
