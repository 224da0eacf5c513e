// SPDX-License-Identifier: Apache-2.0
// The cases real archives have, made from the real files: the other byte
// order, LZ4 compression, damaged, truncated, empty and foreign files,
// missing caches, padding bits and non-finite values. Each decodes exactly
// as the original, or gives an error or warning naming file and byte offset,
// and a damaged file keeps the cycles before the damage.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "file_surgery.hpp"
#include "glider/slocum/binary_file.hpp"
#include "glider/slocum/deployment.hpp"
#include "glider/slocum/lz4_blocks.hpp"
#include "reference.hpp"

namespace {

namespace fs = std::filesystem;
namespace t = glider::slocum::test;
using glider::slocum::BinaryFile;
using glider::slocum::ReadOptions;
using glider::slocum::SlocumError;

// A flight file (2056 sensors, 1/4/8-byte values, factored list, -inf values)
// and a science file that carries its own list (91 sensors: padding bits).
const char* const kFlight = "comet-2016-174-05-003.dbd";
const char* const kScienceWithList = "comet-2019-222-02-155.ebd";

ReadOptions real_options(const std::string& name) {
  ReadOptions options;
  options.cache_dirs = {t::real_cache(name)};
  return options;
}

BinaryFile read_real(const std::string& name) {
  return glider::slocum::read_binary_file(t::real_file(name), real_options(name));
}

fs::path scratch(const std::string& name) { return t::output_dir() / "slocum" / name; }

// Same sensors, same cycles, same values (bit for bit, NaN = NaN) in the
// first `cycles` data cycles (all when npos).
void check_same(const BinaryFile& want, const BinaryFile& got, std::size_t cycles = std::string::npos) {
  CHECK_EQUAL(want.sensors().size(), got.sensors().size());
  if (cycles == std::string::npos) CHECK_EQUAL(want.cycle_count(), got.cycle_count());
  for (std::size_t i = 0; i < want.sensors().size(); ++i) {
    const auto& a = want.series()[i];
    const auto& b = got.series()[i];
    std::size_t k = 0;
    for (; k < a.cycles.size() && a.cycles[k] < cycles; ++k) {
      CHECK_TEXT(k < b.cycles.size(), want.sensors()[i].name.c_str());
      CHECK_EQUAL(a.cycles[k], b.cycles[k]);
      CHECK_TEXT(a.values[k] == b.values[k] || (std::isnan(a.values[k]) && std::isnan(b.values[k])),
                 want.sensors()[i].name.c_str());
    }
    CHECK_EQUAL(k, b.cycles.size());
  }
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string all_warnings(const BinaryFile& file) {
  std::string text;
  for (const auto& w : file.warnings()) text += w.text() + "\n";
  return text;
}

std::string error_of(const fs::path& path, const ReadOptions& options) {
  try {
    glider::slocum::read_binary_file(path, options);
  } catch (const SlocumError& error) {
    return error.what();
  }
  return "(no error)";
}

}  // namespace

TEST_GROUP(SlocumTwins){};

TEST(SlocumTwins, LittleEndianTwinDecodesIdentically) {
  for (const std::string name : {kFlight, kScienceWithList}) {
    const BinaryFile original = read_real(name);
    const std::string twin = t::little_endian_twin(t::read_bytes(t::real_file(name)), original);
    const fs::path path = scratch("little-endian/" + name);
    t::write_bytes(path, twin);
    const BinaryFile decoded = glider::slocum::read_binary_file(path, real_options(name));
    CHECK(decoded.byte_order() == glider::slocum::ByteOrder::kLittle);
    CHECK(original.byte_order() == glider::slocum::ByteOrder::kBig);
    CHECK(decoded.complete());
    check_same(original, decoded);
  }
}

TEST(SlocumTwins, Lz4TwinsDecodeIdenticallyInEitherCase) {
  for (const auto& [name, compressed_name] : {std::pair<std::string, std::string>{kFlight, "comet-2016-174-05-003.dcd"},
                                              {kFlight, "comet-2016-174-05-003.DCD"},
                                              {kScienceWithList, "comet-2019-222-02-155.ecd"},
                                              {"comet-2016-174-05-003.ebd", "comet-2016-174-05-003.ECD"}}) {
    const BinaryFile original = read_real(name);
    const fs::path path = scratch("lz4/" + compressed_name);
    t::write_bytes(path, glider::slocum::compress_blocks(t::read_bytes(t::real_file(name))));
    const BinaryFile decoded = glider::slocum::read_binary_file(path, real_options(name));
    CHECK(decoded.compressed());
    CHECK(decoded.complete());
    check_same(original, decoded);
  }
}

TEST(SlocumTwins, CompressedSensorListCache) {
  const BinaryFile original = read_real(kFlight);
  const std::string crc = original.header().sensor_list_crc;
  const fs::path dir = scratch("ccc-cache");
  t::write_bytes(dir / (crc + ".ccc"),
                 glider::slocum::compress_blocks(t::read_bytes(t::real_cache(kFlight) / (crc + ".cac"))));
  ReadOptions options;
  options.cache_dirs = {dir};
  check_same(original, glider::slocum::read_binary_file(t::real_file(kFlight), options));
}

TEST(SlocumTwins, OwnSensorListIsWrittenToTheCache) {
  const fs::path dir = scratch("written-cache");
  fs::remove_all(dir);
  ReadOptions options;
  options.cache_write_dir = dir;
  const BinaryFile file = glider::slocum::read_binary_file(t::real_file(kScienceWithList), options);
  CHECK_FALSE(file.header().sensor_list_factored);
  const fs::path written = dir / (file.header().sensor_list_crc + ".cac");
  // The glider's own cache file of that list, byte for byte.
  STRCMP_EQUAL(t::read_bytes(t::real_cache(kScienceWithList) / written.filename()).c_str(),
               t::read_bytes(written).c_str());
}

TEST_GROUP(SlocumDamage){};

TEST(SlocumDamage, TruncatedFileKeepsTheCyclesBeforeTheCut) {
  const std::string bytes = t::read_bytes(t::real_file(kFlight));
  const BinaryFile original = read_real(kFlight);
  const t::Layout layout = t::walk(bytes, original);
  const std::size_t k = layout.cycles.size() / 2;
  // Cut inside cycle k's values: cycles 0..k-1 survive.
  const std::size_t cut = layout.cycles[k] + 1 + original.header().state_bytes_per_cycle + 3;
  const fs::path path = scratch("truncated/" + std::string(kFlight));
  t::write_bytes(path, bytes.substr(0, cut));
  const BinaryFile partial = glider::slocum::read_binary_file(path, real_options(kFlight));
  CHECK_FALSE(partial.complete());
  CHECK_EQUAL(k, partial.cycle_count());
  check_same(original, partial, k);
  const std::string warnings = all_warnings(partial);
  CHECK_TEXT(
      contains(warnings, path.string() + ": byte " + std::to_string(layout.cycles[k]) + ": file ends inside cycle"),
      warnings.c_str());
  CHECK_TEXT(contains(warnings, std::to_string(k) + " cycles before it kept"), warnings.c_str());

  // Cut right after a complete cycle: no end marker.
  t::write_bytes(path, bytes.substr(0, layout.cycles[k]));
  const BinaryFile no_end = glider::slocum::read_binary_file(path, real_options(kFlight));
  CHECK_FALSE(no_end.complete());
  check_same(original, no_end, k);
  CHECK(contains(all_warnings(no_end),
                 "byte " + std::to_string(layout.cycles[k]) + ": file ends without the end marker"));

  // Cut inside the header: nothing to decode, an error at the cut.
  t::write_bytes(path, bytes.substr(0, 100));
  const std::string error = error_of(path, real_options(kFlight));
  CHECK_TEXT(contains(error, path.string() + ": byte "), error.c_str());
  CHECK_TEXT(contains(error, "byte 83: file ends inside the ASCII header (truncated)"), error.c_str());
}

TEST(SlocumDamage, GarbageRunStopsAtTheDamagedCycle) {
  std::string bytes = t::read_bytes(t::real_file(kFlight));
  const BinaryFile original = read_real(kFlight);
  const t::Layout layout = t::walk(bytes, original);
  const std::size_t k = layout.cycles.size() / 3;
  for (std::size_t i = 0; i < 200; ++i) bytes[layout.cycles[k] + i] = static_cast<char>(0xA5);
  const fs::path path = scratch("garbage/" + std::string(kFlight));
  t::write_bytes(path, bytes);
  const BinaryFile partial = glider::slocum::read_binary_file(path, real_options(kFlight));
  CHECK_FALSE(partial.complete());
  check_same(original, partial, k);
  const std::string warnings = all_warnings(partial);
  CHECK_TEXT(contains(warnings, "byte " + std::to_string(layout.cycles[k]) + ": byte 0xa5 where a cycle"),
             warnings.c_str());
}

TEST(SlocumDamage, CorruptCompressedBlockKeepsTheBlocksBefore) {
  const BinaryFile original = read_real(kFlight);
  std::string compressed = glider::slocum::compress_blocks(t::read_bytes(t::real_file(kFlight)), 4096);
  // The second block's size field claims more than the file holds.
  const std::size_t first =
      (static_cast<unsigned char>(compressed[0]) << 8) | static_cast<unsigned char>(compressed[1]);
  const std::size_t second = 2 + first;
  compressed[second] = static_cast<char>(0xFF);
  compressed[second + 1] = static_cast<char>(0xFF);
  const fs::path path = scratch("lz4-damaged/comet-2016-174-05-003.dcd");
  t::write_bytes(path, compressed);
  const BinaryFile partial = glider::slocum::read_binary_file(path, real_options(kFlight));
  CHECK_FALSE(partial.complete());
  const std::string warnings = all_warnings(partial);
  CHECK_TEXT(contains(warnings, "byte " + std::to_string(second) + ": LZ4 block of 65535 bytes"), warnings.c_str());
  check_same(original, partial, partial.cycle_count());
}

TEST(SlocumDamage, MissingCacheNamesTheCrcAndWhereItLooked) {
  const fs::path empty = scratch("no-cache");
  fs::create_directories(empty);
  ReadOptions options;
  options.cache_dirs = {empty};
  const std::string error = error_of(t::real_file(kFlight), options);
  CHECK_TEXT(contains(error, t::real_file(kFlight).string() + ": byte 0: sensor list 11d38bfd is factored out"),
             error.c_str());
  CHECK_TEXT(contains(error, "11d38bfd.cac"), error.c_str());
  CHECK_TEXT(contains(error, empty.string()), error.c_str());
}

TEST(SlocumDamage, OtherEncodingVersionIsRefused) {
  std::string bytes = t::read_bytes(t::real_file(kFlight));
  const std::size_t at = bytes.find("encoding_ver:    5");
  bytes[at + 17] = '4';
  const fs::path path = scratch("version/" + std::string(kFlight));
  t::write_bytes(path, bytes);
  const std::string error = error_of(path, real_options(kFlight));
  CHECK_TEXT(contains(error, path.string() + ": byte 0: encoding version 4, only version 5 is supported"),
             error.c_str());
}

TEST(SlocumDamage, EmptyAndForeignFilesAreRefused) {
  const fs::path empty = scratch("empty/x-2016-1-0-0.dbd");
  t::write_bytes(empty, "");
  CHECK(contains(error_of(empty, {}), empty.string() + ": byte 0: empty file"));
  const fs::path empty_lz4 = scratch("empty/x-2016-1-0-0.dcd");
  t::write_bytes(empty_lz4, "");
  CHECK(contains(error_of(empty_lz4, {}), "empty file"));
  const fs::path text = scratch("foreign/x-2016-1-0-0.dbd");
  t::write_bytes(text, "m_present_time,m_depth\n1,2\n");
  const std::string error = error_of(text, {});
  CHECK_TEXT(contains(error, "byte 0: header line without ':'") || contains(error, "not a DINKUM binary file"),
             error.c_str());
}

TEST(SlocumDamage, BadKnownBytesAreRefused) {
  const BinaryFile original = read_real(kFlight);
  std::string bytes = t::read_bytes(t::real_file(kFlight));
  const std::size_t known = original.binary_offset();
  bytes[known + 2] = 0x56;  // neither 0x1234 nor 0x3412
  const fs::path path = scratch("known-bytes/" + std::string(kFlight));
  t::write_bytes(path, bytes);
  const std::string error = error_of(path, real_options(kFlight));
  CHECK_TEXT(contains(error, "byte " + std::to_string(known + 2) + ": known-bytes short reads 0x56 0x34"),
             error.c_str());
  bytes = t::read_bytes(t::real_file(kFlight));
  bytes[known + 7] = static_cast<char>(bytes[known + 7] ^ 1);  // the float's last bit
  t::write_bytes(path, bytes);
  CHECK(contains(error_of(path, real_options(kFlight)), "byte " + std::to_string(known + 4) + ": known-bytes float"));
}

TEST(SlocumDamage, PaddingBitsAreReportedAndIgnored) {
  const BinaryFile original = read_real(kScienceWithList);
  CHECK(original.sensors().size() % 4 != 0);
  std::string bytes = t::read_bytes(t::real_file(kScienceWithList));
  const t::Layout layout = t::walk(bytes, original);
  const std::size_t last_state = layout.cycles[1] + original.header().state_bytes_per_cycle;
  bytes[last_state] = static_cast<char>(bytes[last_state] | 0x01);
  const fs::path path = scratch("padding/" + std::string(kScienceWithList));
  t::write_bytes(path, bytes);
  const BinaryFile decoded = glider::slocum::read_binary_file(path, {});
  CHECK(decoded.complete());
  check_same(original, decoded);
  const std::string warnings = all_warnings(decoded);
  CHECK_TEXT(contains(warnings, "byte " + std::to_string(last_state) + ": padding bits set"), warnings.c_str());
}

TEST(SlocumDamage, NonFiniteValuesAreNamedWithTheirOffset) {
  const BinaryFile file = read_real("comet-2016-174-05-000.dbd");
  const std::string bytes = t::read_bytes(t::real_file("comet-2016-174-05-000.dbd"));
  const auto it = std::find_if(file.warnings().begin(), file.warnings().end(),
                               [](const auto& w) { return w.sensor == "m_time_til_wpt"; });
  CHECK(it != file.warnings().end());
  CHECK(contains(it->problem, "non-finite values (first: -inf"));
  // The offset points at the stored big-endian float -inf (ff 80 00 00).
  CHECK_EQUAL(0xFF, static_cast<unsigned char>(bytes[it->offset]));
  CHECK_EQUAL(0x80, static_cast<unsigned char>(bytes[it->offset + 1]));
  // In a flight log they are empty, with the warning kept for the column.
  glider::slocum::DeploymentOptions options;
  options.columns = {"m_time_til_wpt"};
  const auto deployment = glider::slocum::read_deployment({t::real_file("comet-2016-174-05-000.dbd")}, options);
  for (const double v : deployment.log.column("m_time_til_wpt")) CHECK(!std::isinf(v));
  CHECK_EQUAL(1U, deployment.warnings.size());
  CHECK(contains(deployment.warnings.front().problem, "left empty in the log"));
}

TEST(SlocumDamage, ABadFileDoesNotStopTheSet) {
  const fs::path dir = scratch("set");
  fs::remove_all(dir);
  for (const char* name : {"comet-2016-174-05-003.dbd", "comet-2016-174-05-005.dbd", "comet-2016-174-05-007.dbd"}) {
    t::write_bytes(dir / name, t::read_bytes(t::real_file(name)));
  }
  t::write_bytes(dir / "comet-2016-174-05-005.dbd", "");  // the middle one is lost
  glider::slocum::DeploymentOptions options;
  options.read.cache_dirs = {t::real_cache(kFlight)};
  const auto deployment = glider::slocum::read_deployment(glider::slocum::deployment_files({dir.string()}), options);
  CHECK_EQUAL(2U, deployment.files.size());
  const std::size_t expected = read_real("comet-2016-174-05-003.dbd").cycle_count() - 1 +
                               read_real("comet-2016-174-05-007.dbd").cycle_count() - 1;
  CHECK_EQUAL(expected, deployment.log.rows());
  CHECK_EQUAL(1U, deployment.warnings.size());
  CHECK(contains(deployment.warnings.front().text(), "comet-2016-174-05-005.dbd: byte 0: empty file (file skipped"));
}

TEST(SlocumDamage, ASensorListReadForAnotherFileMustFitTheHeader) {
  // Found by fuzz.slocum_binary: a header that says fewer sensors per cycle
  // under a CRC already read for another file of the set got that file's
  // list, and the decoder shifted by a negative padding.
  std::string bytes = t::read_bytes(t::real_file(kFlight));
  const auto replace = [&bytes](const std::string& from, const std::string& to) {
    const std::size_t at = bytes.find(from);
    CHECK(at != std::string::npos);
    bytes.replace(at, from.size(), to);
  };
  replace("sensors_per_cycle:    2056", "sensors_per_cycle:    2000");
  replace("state_bytes_per_cycle:    514", "state_bytes_per_cycle:    500");
  const fs::path path = scratch("memo/comet-2016-174-05-004.dbd");
  t::write_bytes(path, bytes);
  glider::slocum::SensorListMemo memo;
  ReadOptions options = real_options(kFlight);
  options.memo = &memo;
  glider::slocum::read_binary_file(t::real_file(kFlight), options);  // reads and keeps list 11d38bfd
  const std::string error = error_of(path, options);
  CHECK_TEXT(contains(error,
                      "comet-2016-174-05-004.dbd: byte 0: sensor list 11d38bfd (read for another file of the "
                      "set) has 2056 sensors, this header says 2000 per cycle"),
             error.c_str());
}
