// SPDX-License-Identifier: Apache-2.0
#pragma once
// A fixed ring of bytes waiting for the modem: the dialog and the console
// append text, and each cycle as much as the link takes is written. Nothing
// here allocates; a full queue drops the text and counts it (never blocks).
#include <array>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string_view>

namespace glider::fw::comms {

template <std::size_t N>
class OutputQueue {
 public:
  bool append(std::string_view text) {
    if (text.size() > N - size_) {
      dropped_ += text.size();
      return false;
    }
    for (const char c : text) {
      bytes_[(head_ + size_) % N] = static_cast<std::uint8_t>(c);
      ++size_;
    }
    return true;
  }

  // printf into a stack line (at most 255 characters, longer is cut).
  __attribute__((format(printf, 2, 3))) bool appendf(const char* format, ...) {
    char line[256];
    va_list args;
    va_start(args, format);
    const int n = std::vsnprintf(line, sizeof line, format, args);
    va_end(args);
    if (n < 0) return false;
    const std::size_t length =
        static_cast<std::size_t>(n) < sizeof line ? static_cast<std::size_t>(n) : sizeof line - 1;
    return append(std::string_view(line, length));
  }

  // The contiguous bytes at the head (for a write), then consume() what went out.
  std::span<const std::uint8_t> front() const {
    const std::size_t run = head_ + size_ <= N ? size_ : N - head_;
    return {bytes_.data() + head_, run};
  }
  void consume(std::size_t n) {
    if (n > size_) n = size_;
    head_ = (head_ + n) % N;
    size_ -= n;
  }
  void clear() { head_ = size_ = 0; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t free_space() const { return N - size_; }
  std::uint64_t dropped() const { return dropped_; }

 private:
  std::array<std::uint8_t, N> bytes_{};
  std::size_t head_ = 0;
  std::size_t size_ = 0;
  std::uint64_t dropped_ = 0;
};

}  // namespace glider::fw::comms
