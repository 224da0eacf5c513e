// SPDX-License-Identifier: Apache-2.0
#pragma once
// NMEA 0183 framing and sentence checks, shared by the GPS and the compass.
// Pure code (no I/O), fixed buffers, no allocation: the serial drivers feed
// it whatever bytes the port had, in any pieces.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace glider::hal_linux {

// NMEA 0183: at most 82 characters from '$' to the end of line.
constexpr std::size_t kMaxNmeaSentence = 82;
constexpr std::size_t kMaxNmeaFields = 24;

enum class NmeaCheck { kOk, kNoChecksum, kBadChecksum, kMalformed };

// A checked sentence split at commas, the address field first ("GPGGA").
// The views point into the caller's line.
struct NmeaSentence {
  std::array<std::string_view, kMaxNmeaFields> fields{};
  std::size_t count = 0;

  std::string_view address() const { return fields[0]; }
  // The sentence formatter without the talker ("GGA" of "GPGGA", "GNGGA").
  std::string_view formatter() const { return fields[0].size() == 5 ? fields[0].substr(2) : fields[0]; }
  std::string_view field(std::size_t i) const { return i < count ? fields[i] : std::string_view{}; }
};

// `line` is one sentence from '$' to the checksum, without the line end.
// The checksum is required (NMEA makes it optional; a glider's sensors send
// it and a sentence without one cannot be trusted).
NmeaCheck check_nmea(std::string_view line, NmeaSentence& out);

// Fields as numbers. Empty when the field is empty, not a number or not finite.
std::optional<double> nmea_number(std::string_view field);
std::optional<int> nmea_integer(std::string_view field);
// "ddmm.mmmm" / "dddmm.mmmm" and the hemisphere letter as signed degrees.
std::optional<double> nmea_coordinate(std::string_view value, std::string_view hemisphere, double max_degrees);

struct NmeaFramerStats {
  std::uint64_t lines = 0;          // complete candidate sentences handed on
  std::uint64_t garbage_bytes = 0;  // bytes outside any sentence
  std::uint64_t overlong = 0;       // sentences longer than NMEA allows (dropped)
};

// Cuts a byte stream into lines that start with '$'. A '$' inside a
// sentence starts a new one (the old one was cut short); CR or LF ends one.
class NmeaFramer {
 public:
  template <typename OnLine>
  void feed(std::string_view bytes, OnLine&& on_line) {
    for (const char c : bytes) {
      if (c == '$') {
        if (length_ > 0) ++stats_.garbage_bytes;  // a partial sentence, cut by a new start
        length_ = 0;
        buffer_[length_++] = c;
      } else if (length_ == 0) {
        if (c != '\r' && c != '\n') ++stats_.garbage_bytes;
      } else if (c == '\r' || c == '\n') {
        ++stats_.lines;
        on_line(std::string_view(buffer_.data(), length_));
        length_ = 0;
      } else if (length_ < kMaxNmeaSentence) {
        buffer_[length_++] = c;
      } else {
        ++stats_.overlong;
        length_ = 0;
      }
    }
  }
  const NmeaFramerStats& stats() const { return stats_; }

 private:
  std::array<char, kMaxNmeaSentence> buffer_{};
  std::size_t length_ = 0;
  NmeaFramerStats stats_;
};

}  // namespace glider::hal_linux
