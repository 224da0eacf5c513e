// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: bytes to the Slocum binary decoder (glider_slocum). The
// first byte picks the form: even = an uncompressed .dbd-type file, odd = an
// LZ4 block stream (.dcd-type). Factored sensor lists are found in the real
// caches of tests/data/real/dbd, so mutations of the real seeds reach the
// cycle decoder. Every accepted file must be self-consistent: one series per
// sensor, cycles in range and increasing, get() for every sensor.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "glider/slocum/binary_file.hpp"

namespace {

const glider::slocum::ReadOptions& options() {
  static const glider::slocum::ReadOptions read = [] {
    // Each cache is parsed once, not per input (the decoder is the target).
    static glider::slocum::SensorListMemo memo;
    glider::slocum::ReadOptions o;
    o.memo = &memo;
    const std::string real = std::string(GLIDER_SOURCE_DIR) + "/tests/data/real/dbd/";
    o.cache_dirs = {real + "comet-2016/cac", real + "comet-2019/cac"};
    return o;
  }();
  return read;
}

// An invariant broken: say which, then crash so libFuzzer keeps the input.
void check(bool condition, int line) {
  if (condition) return;
  std::fprintf(stderr, "fuzz_slocum_binary.cpp:%d: invariant broken\n", line);
  std::abort();
}
#define CHECK_INVARIANT(condition) check((condition), __LINE__)

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool compressed = (data[0] & 1U) != 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const glider::slocum::BinaryFile file = glider::slocum::parse_binary_file(bytes, "fuzz.dbd", options(), compressed);
    CHECK_INVARIANT(file.series().size() == file.sensors().size());
    for (std::size_t i = 0; i < file.sensors().size(); ++i) {
      const auto& series = file.series()[i];
      CHECK_INVARIANT(series.cycles.size() == series.values.size());
      for (std::size_t k = 0; k < series.cycles.size(); ++k) {
        CHECK_INVARIANT(series.cycles[k] < file.cycle_count());
        CHECK_INVARIANT(k == 0 || series.cycles[k] > series.cycles[k - 1]);
      }
    }
    // get() on a few sensors (by name: a linear lookup, so not all 2000).
    for (std::size_t i = 0; i < file.sensors().size(); i += 1 + file.sensors().size() / 16) {
      const auto got = glider::slocum::get(file, file.sensors()[i].name);
      CHECK_INVARIANT(got.time.size() == got.value.size() && got.time.size() <= file.series()[i].cycles.size());
    }
  } catch (const glider::slocum::SlocumError&) {
    // Refused with a message: fine.
  }
  return 0;
}
