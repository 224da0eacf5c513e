// SPDX-License-Identifier: Apache-2.0
#include "cycle_decoder.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>

namespace glider::slocum::detail {
namespace {

constexpr char kKnownBytesTag = 's';
constexpr char kKnownBytesTag2 = 'a';
constexpr char kCycleTag = 'd';
constexpr char kEndTag = 'X';
constexpr std::size_t kKnownBytesSize = 16;
constexpr float kKnownFloat = 123.456F;
constexpr double kKnownDouble = 123456789.12345;

// The 2-bit states, most significant pair first in each state byte.
constexpr unsigned kNotUpdated = 0;
constexpr unsigned kSameValue = 1;
constexpr unsigned kNewValue = 2;

template <typename Unsigned>
Unsigned load(const char* p, bool swap) {
  Unsigned raw;
  std::memcpy(&raw, p, sizeof raw);
  if (swap) {
    if constexpr (sizeof(Unsigned) == 2) raw = __builtin_bswap16(raw);
    if constexpr (sizeof(Unsigned) == 4) raw = __builtin_bswap32(raw);
    if constexpr (sizeof(Unsigned) == 8) raw = __builtin_bswap64(raw);
  }
  return raw;
}

bool needs_swap(ByteOrder order) { return (order == ByteOrder::kBig) != (std::endian::native == std::endian::big); }

std::string hex_byte(unsigned char c) {
  constexpr char kDigits[] = "0123456789abcdef";
  return std::string("0x") + kDigits[c >> 4] + kDigits[c & 15];
}

// One value of `bytes` stored bytes: 1 and 2 are signed integers, 4 a
// float, 8 a double (what the glider writes).
double decode_value(const char* p, int bytes, bool swap) {
  switch (bytes) {
    case 1:
      return static_cast<double>(static_cast<std::int8_t>(*p));
    case 2:
      return static_cast<double>(static_cast<std::int16_t>(load<std::uint16_t>(p, swap)));
    case 4:
      return static_cast<double>(std::bit_cast<float>(load<std::uint32_t>(p, swap)));
    default:
      return std::bit_cast<double>(load<std::uint64_t>(p, swap));
  }
}

// A state byte's fields, masked to one bit per field at bits 6, 4, 2, 0
// (most significant pair = first sensor), as a 4-bit set: bit f for field f.
constexpr std::array<std::uint8_t, 256> kFieldsOf = [] {
  std::array<std::uint8_t, 256> table{};
  for (unsigned m = 0; m < 256; ++m) {
    unsigned fields = 0;
    for (unsigned f = 0; f < 4; ++f) fields |= ((m >> (6 - 2 * f)) & 1U) << f;
    table[m] = static_cast<std::uint8_t>(fields);
  }
  return table;
}();

// Non-finite values are kept (dbdreader keeps them, and Slocum writes -inf
// e.g. for "no waypoint time"), but said: one warning per sensor at the end.
struct NonFinite {
  std::size_t count = 0;
  std::size_t first_offset = 0;
  double first_value = 0.0;
};

}  // namespace

ByteOrder read_known_bytes(std::string_view bytes, std::size_t& pos, const std::string& source) {
  if (bytes.size() - pos < kKnownBytesSize) {
    throw SlocumError(source, pos,
                      "file ends inside the known-bytes cycle (" + std::to_string(bytes.size() - pos) + " of " +
                          std::to_string(kKnownBytesSize) + " bytes)");
  }
  const char* p = bytes.data() + pos;
  if (p[0] != kKnownBytesTag || p[1] != kKnownBytesTag2) {
    throw SlocumError(source, pos,
                      "no known-bytes cycle after the header: expected 's' 'a', found " +
                          hex_byte(static_cast<unsigned char>(p[0])) + " " +
                          hex_byte(static_cast<unsigned char>(p[1])));
  }
  const auto b0 = static_cast<unsigned char>(p[2]);
  const auto b1 = static_cast<unsigned char>(p[3]);
  ByteOrder order;
  if (b0 == 0x12 && b1 == 0x34) {
    order = ByteOrder::kBig;
  } else if (b0 == 0x34 && b1 == 0x12) {
    order = ByteOrder::kLittle;
  } else {
    throw SlocumError(
        source, pos + 2,
        "known-bytes short reads " + hex_byte(b0) + " " + hex_byte(b1) + ", not 0x1234 in either byte order");
  }
  const bool swap = needs_swap(order);
  const float f = std::bit_cast<float>(load<std::uint32_t>(p + 4, swap));
  const double d = std::bit_cast<double>(load<std::uint64_t>(p + 8, swap));
  if (f != kKnownFloat) {
    throw SlocumError(source, pos + 4, "known-bytes float does not read back as 123.456: not IEEE-754 single");
  }
  if (d != kKnownDouble) {
    throw SlocumError(source, pos + 8, "known-bytes double does not read back as 123456789.12345: not IEEE-754 double");
  }
  pos += kKnownBytesSize;
  return order;
}

DecodedCycles decode_cycles(std::string_view bytes, std::size_t pos, const Header& header, const SensorList& sensors,
                            std::optional<std::size_t> time_index, ByteOrder order, bool skip_first_cycle,
                            const std::string& source) {
  DecodedCycles out;
  const std::size_t n = sensors.size();
  const std::size_t state_bytes = header.state_bytes_per_cycle;
  const bool swap = needs_swap(order);
  std::vector<int> sizes(n);
  for (std::size_t i = 0; i < n; ++i) sizes[i] = sensors[i].bytes;
  if (state_bytes * 4 < n || state_bytes * 4 - n >= 4) {  // the callers check it; the decoder relies on it
    throw SlocumError(source, pos,
                      std::to_string(state_bytes) + " state bytes per cycle do not hold " + std::to_string(n) +
                          " sensors' 2-bit states");
  }
  // Bits of the last state byte beyond the last sensor must be zero.
  const unsigned padding_fields = static_cast<unsigned>(state_bytes * 4 - n);
  const unsigned padding_mask = padding_fields == 0 ? 0U : ((1U << (2 * padding_fields)) - 1U);
  std::size_t padding_cycles = 0;
  std::size_t first_padding_offset = 0;
  std::size_t invalid_states = 0;
  std::size_t first_invalid_offset = 0;
  std::map<std::size_t, NonFinite> non_finite;
  const char* data = bytes.data();
  const std::size_t size = bytes.size();

  // Pass 1: walk the cycles (tag, state bytes, value bytes), stop at the end
  // marker or the damage, and count each sensor's values, so pass 2 fills
  // exactly sized arrays and a damaged cycle is never half applied.
  std::vector<std::size_t> cycle_offsets;
  cycle_offsets.reserve((size - pos) / (state_bytes + 1) + 1);
  // Per state byte and set of its 4 fields (bit f for the f-th sensor of
  // the byte): the value bytes when those fields are new, and how many
  // cycles had those fields set (new or same). A byte at a time instead of
  // a field at a time (the decoder: 100 M -> 83 M instructions on comet-2016).
  std::vector<std::uint32_t> group_bytes(state_bytes * 16, 0);
  for (std::size_t b = 0; b < state_bytes; ++b) {
    for (unsigned fields = 0; fields < 16; ++fields) {
      for (unsigned f = 0; f < 4 && b * 4 + f < n; ++f) {
        if ((fields >> f) & 1U) group_bytes[b * 16 + fields] += static_cast<std::uint32_t>(sizes[b * 4 + f]);
      }
    }
  }
  std::vector<std::uint32_t> pattern_counts(state_bytes * 16, 0);
  while (true) {
    const std::size_t cycle = cycle_offsets.size();
    if (pos >= size) {
      out.warnings.push_back({source, pos,
                              "file ends without the end marker 'X' after " + std::to_string(cycle) +
                                  " cycles (truncated?): the cycles before are kept"});
      break;
    }
    const char tag = data[pos];
    if (tag == kEndTag) {
      out.complete = true;
      if (pos + 1 != size) {
        out.warnings.push_back(
            {source, pos + 1, std::to_string(size - pos - 1) + " bytes after the end marker 'X' ignored"});
      }
      break;
    }
    if (tag != kCycleTag) {
      out.warnings.push_back({source, pos,
                              "byte " + hex_byte(static_cast<unsigned char>(tag)) +
                                  " where a cycle ('d') or the end ('X') should start: data damaged here; " +
                                  std::to_string(cycle) + " cycles before it kept, the rest of the file not read"});
      break;
    }
    if (size - pos - 1 < state_bytes) {
      out.warnings.push_back({source, pos,
                              "file ends inside the state bytes of cycle " + std::to_string(cycle) +
                                  " (truncated): " + std::to_string(cycle) + " cycles before it kept"});
      break;
    }
    const auto* states = reinterpret_cast<const unsigned char*>(data + pos + 1);
    std::size_t value_bytes = 0;
    const std::uint32_t counted = (skip_first_cycle && cycle == 0) ? 0U : 1U;
    for (std::size_t b = 0; b < state_bytes; ++b) {
      const unsigned s = states[b];
      if (s == 0) continue;
      value_bytes += group_bytes[b * 16 + kFieldsOf[(s >> 1) & ~s & 0x55U]];
      pattern_counts[b * 16 + kFieldsOf[(s ^ (s >> 1)) & 0x55U]] += counted;
    }
    const std::size_t values_start = pos + 1 + state_bytes;
    if (size - values_start < value_bytes) {
      out.warnings.push_back({source, pos,
                              "file ends inside cycle " + std::to_string(cycle) + " (" + std::to_string(value_bytes) +
                                  " value bytes announced, " + std::to_string(size - values_start) +
                                  " left; truncated): " + std::to_string(cycle) + " cycles before it kept"});
      // Its states were counted: take them back.
      for (std::size_t b = 0; b < state_bytes; ++b) {
        const unsigned s = states[b];
        if (s != 0) pattern_counts[b * 16 + kFieldsOf[(s ^ (s >> 1)) & 0x55U]] -= counted;
      }
      break;
    }
    if (padding_mask != 0 && (states[state_bytes - 1] & padding_mask) != 0) {
      if (padding_cycles++ == 0) first_padding_offset = pos + state_bytes;
    }
    cycle_offsets.push_back(pos);
    pos = values_start + value_bytes;
  }

  std::vector<std::uint32_t> counts(n, 0);
  for (std::size_t b = 0; b < state_bytes; ++b) {
    for (unsigned fields = 1; fields < 16; ++fields) {
      const std::uint32_t cycles = pattern_counts[b * 16 + fields];
      if (cycles == 0) continue;
      for (unsigned f = 0; f < 4 && b * 4 + f < n; ++f) {
        if ((fields >> f) & 1U) counts[b * 4 + f] += cycles;
      }
    }
  }

  // Pass 2: the values, into arrays of the counted size (written through
  // cursors: the 2000 arrays are the decoder's hot spot).
  out.series.resize(n);
  std::vector<std::uint32_t*> cycle_cursor(n);
  std::vector<double*> value_cursor(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.series[i].cycles.resize(counts[i]);
    out.series[i].values.resize(counts[i]);
    cycle_cursor[i] = out.series[i].cycles.data();
    value_cursor[i] = out.series[i].values.data();
  }
  std::vector<double> held(n, std::numeric_limits<double>::quiet_NaN());
  out.cycle_time.resize(cycle_offsets.size());
  for (std::size_t cycle = 0; cycle < cycle_offsets.size(); ++cycle) {
    const std::size_t at = cycle_offsets[cycle];
    const auto* states = reinterpret_cast<const unsigned char*>(data + at + 1);
    const char* value = data + at + 1 + state_bytes;
    const bool keep = !(skip_first_cycle && cycle == 0);
    const auto cycle_index = static_cast<std::uint32_t>(cycle);
    for (std::size_t b = 0; b < state_bytes; ++b) {
      const unsigned s = states[b];
      if (s == 0) continue;
      const std::size_t base = b * 4;
      for (unsigned f = 0; f < 4 && base + f < n; ++f) {
        const std::size_t i = base + f;
        const unsigned state = (s >> (6 - 2 * f)) & 3U;
        if (state == kNotUpdated) continue;
        if (state == kNewValue) {
          const double v = decode_value(value, sizes[i], swap);
          if (!std::isfinite(v)) {
            NonFinite& record = non_finite[i];
            if (record.count++ == 0) {
              record.first_offset = static_cast<std::size_t>(value - data);
              record.first_value = v;
            }
          }
          held[i] = v;
          value += sizes[i];
        } else if (state != kSameValue) {
          if (invalid_states++ == 0) first_invalid_offset = at + 1 + b;
          continue;
        }
        if (keep) {
          *cycle_cursor[i]++ = cycle_index;
          *value_cursor[i]++ = held[i];
        }
      }
    }
    out.cycle_time[cycle] = time_index ? held[*time_index] : std::numeric_limits<double>::quiet_NaN();
  }

  if (padding_cycles > 0) {
    out.warnings.push_back({source, first_padding_offset,
                            "padding bits set in the last state byte of " + std::to_string(padding_cycles) +
                                " cycles (first here): ignored"});
  }
  if (invalid_states > 0) {
    out.warnings.push_back({source, first_invalid_offset,
                            std::to_string(invalid_states) + " sensor states of 3 (undefined; first here): read as "
                                                             "'not updated'"});
  }
  for (const auto& [i, record] : non_finite) {
    std::string value = std::isnan(record.first_value) ? "nan" : (record.first_value > 0 ? "inf" : "-inf");
    out.warnings.push_back(
        {source, record.first_offset,
         sensors[i].name + ": " + std::to_string(record.count) + " non-finite values (first: " + value + ", here)",
         sensors[i].name});
  }
  return out;
}

}  // namespace glider::slocum::detail
