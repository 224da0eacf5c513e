// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading Slocum gliders' own binary data files (DINKUM binary, encoding
// version 5): .dbd .ebd .sbd .tbd .mbd .nbd and their LZ4-compressed forms
// .dcd .ecd .scd .tcd .mcd .ncd, with the sensor list in the file or in a
// <crc>.cac (.ccc compressed) cache file. docs/slocum-binary.md describes the
// format and how each case is tested.
//
// A file is decoded whole into one series per sensor: the data cycles in which
// the sensor was set, either with a new value or "updated with the same
// value" (which repeats the held value), exactly as dbdreader's get() returns
// them. Damage is never silent: header problems throw SlocumError naming the
// file and byte offset; damage inside the cycles keeps the cycles before it
// and adds a warning (BinaryFile::complete() is false).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace glider::slocum {

// "file: byte N: problem" (offset into the decompressed stream for .?cd files).
class SlocumError : public std::runtime_error {
 public:
  SlocumError(std::string file, std::size_t offset, const std::string& problem);
  const std::string& file() const { return file_; }
  std::size_t offset() const { return offset_; }

 private:
  std::string file_;
  std::size_t offset_;
};

// A problem that did not stop the reading (partial file, padding bits set...).
struct Warning {
  Warning() = default;
  Warning(std::string file_, std::size_t offset_, std::string problem_, std::string sensor_ = {})
      : file(std::move(file_)), offset(offset_), problem(std::move(problem_)), sensor(std::move(sensor_)) {}
  std::string file;
  std::size_t offset = 0;
  std::string problem;
  std::string sensor;        // set when the warning is about one sensor's values
  std::string text() const;  // "file: byte N: problem"
};

enum class ByteOrder { kBig, kLittle };

struct Sensor {
  std::string name;
  std::string unit;
  int bytes = 0;  // 1, 2, 4 or 8 stored bytes per new value
};

struct Header {
  std::vector<std::pair<std::string, std::string>> tags;  // the ASCII lines, in order
  int encoding_version = 0;
  std::size_t total_num_sensors = 0;
  std::size_t sensors_per_cycle = 0;
  std::size_t state_bytes_per_cycle = 0;
  std::string sensor_list_crc;  // lower case
  bool sensor_list_factored = false;
  std::optional<std::string> tag(std::string_view key) const;
};

// One sensor's decoded values: the data cycles (0-based, the file's first
// data cycle included in the count) in which it was set, and the value.
struct SensorSeries {
  std::vector<std::uint32_t> cycles;
  std::vector<double> values;
};

using SensorList = std::vector<Sensor>;

// Sensor lists already read, by CRC: the files of a deployment share one or
// two lists, and parsing a 2000-line cache once instead of per file is most
// of a small file's reading time.
struct SensorListMemo {
  std::map<std::string, std::shared_ptr<const SensorList>, std::less<>> by_crc;
};

struct ReadOptions {
  // Directories searched, in order, for <crc>.cac / <crc>.ccc when the file's
  // sensor list is factored out. Empty: the file's own directory and its cac/.
  std::vector<std::filesystem::path> cache_dirs;
  // When set, a file that carries its own sensor list writes it here as
  // <crc>.cac (if not there yet), so later factored files of the same glider
  // can be read.
  std::optional<std::filesystem::path> cache_write_dir;
  // dbdreader's default: the file-open cycle holds stale values and is not
  // returned (it is still decoded: it sets the held values).
  bool skip_first_cycle = true;
  // Optional, shared by the reads of one set (not owned).
  SensorListMemo* memo = nullptr;
};

class BinaryFile {
 public:
  const std::string& source() const { return source_; }
  const Header& header() const { return header_; }
  const SensorList& sensors() const { return *sensors_; }
  ByteOrder byte_order() const { return byte_order_; }
  bool compressed() const { return compressed_; }
  std::size_t binary_offset() const { return binary_offset_; }  // the known-bytes cycle
  std::size_t decompressed_size() const { return decompressed_size_; }
  // m_present_time, or sci_m_present_time in a science file.
  const std::string& time_variable() const { return time_variable_; }
  bool is_science() const { return time_variable_ == "sci_m_present_time"; }
  // Data cycles decoded (the first included), and the time variable's held
  // value in each (NaN before it was first set).
  std::size_t cycle_count() const { return cycle_time_.size(); }
  const std::vector<double>& cycle_time() const { return cycle_time_; }
  const std::vector<SensorSeries>& series() const { return series_; }
  // Index into sensors()/series(), or nullopt.
  std::optional<std::size_t> index_of(std::string_view name) const;
  // True when every cycle up to the end marker was read.
  bool complete() const { return complete_; }
  const std::vector<Warning>& warnings() const { return warnings_; }

 private:
  friend BinaryFile parse_binary_file(std::string_view, const std::string&, const ReadOptions&, bool);
  std::string source_;
  Header header_;
  std::shared_ptr<const SensorList> sensors_;
  ByteOrder byte_order_ = ByteOrder::kBig;
  bool compressed_ = false;
  std::size_t binary_offset_ = 0;
  std::size_t decompressed_size_ = 0;
  std::string time_variable_;
  std::vector<double> cycle_time_;
  std::vector<SensorSeries> series_;
  bool complete_ = false;
  std::vector<Warning> warnings_;
};

// True for .?cd/.ccc names (case-insensitive): LZ4 block stream.
bool is_compressed_name(const std::filesystem::path& path);
// True for the twelve data file extensions (either case).
bool is_binary_data_name(const std::filesystem::path& path);

// Reads and decodes one file; throws SlocumError when nothing can be decoded
// (cannot open, empty, not a DINKUM file, other encoding version, missing
// cache, bad known bytes).
BinaryFile read_binary_file(const std::filesystem::path& path, const ReadOptions& options = {});
// The same on bytes in memory; `compressed` says whether they are an LZ4
// block stream. source_name stands for the path in messages and for finding
// the default cache directories.
BinaryFile parse_binary_file(std::string_view bytes, const std::string& source_name, const ReadOptions& options = {},
                             bool compressed = false);

// dbdreader's get(name) with its defaults: (time, value) of every cycle the
// sensor was set (skipping the first when the options said so). Lat/lon
// sensors (see lat_lon.hpp) drop values outside +-9000/18000 (NMEA) and are
// converted to decimal degrees unless `nmea` is true.
struct TimeSeries {
  std::vector<double> time;
  std::vector<double> value;
};
TimeSeries get(const BinaryFile& file, std::string_view name, bool nmea_lat_lon = false);

}  // namespace glider::slocum
