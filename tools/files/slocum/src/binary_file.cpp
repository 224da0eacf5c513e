// SPDX-License-Identifier: Apache-2.0
#include "glider/slocum/binary_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "ascii_header.hpp"
#include "cycle_decoder.hpp"
#include "glider/slocum/lat_lon.hpp"
#include "glider/slocum/lz4_blocks.hpp"
#include "sensor_cache.hpp"

namespace glider::slocum {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string read_file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SlocumError(path.string(), 0, std::string("cannot open: ") + std::strerror(errno));
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  std::string bytes;
  if (!error) {
    bytes.resize(size);
    in.read(bytes.data(), static_cast<std::streamsize>(size));
    bytes.resize(static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad() || error) throw SlocumError(path.string(), 0, "read error");
  return bytes;
}

}  // namespace

SlocumError::SlocumError(std::string file, std::size_t offset, const std::string& problem)
    : std::runtime_error(Warning{file, offset, problem}.text()), file_(std::move(file)), offset_(offset) {}

std::string Warning::text() const { return file + ": byte " + std::to_string(offset) + ": " + problem; }

std::optional<std::string> Header::tag(std::string_view key) const {
  const auto it = std::find_if(tags.begin(), tags.end(), [key](const auto& tag) { return tag.first == key; });
  if (it == tags.end()) return std::nullopt;
  return it->second;
}

std::optional<std::size_t> BinaryFile::index_of(std::string_view name) const {
  const SensorList& list = *sensors_;
  const auto it = std::find_if(list.begin(), list.end(), [name](const Sensor& s) { return s.name == name; });
  if (it == list.end()) return std::nullopt;
  return static_cast<std::size_t>(it - list.begin());
}

bool is_compressed_name(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".ccc") return true;
  return ext.size() == 4 && std::string_view("demnst").find(ext[1]) != std::string_view::npos && ext[2] == 'c' &&
         ext[3] == 'd';
}

bool is_binary_data_name(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext.size() == 4 && std::string_view("demnst").find(ext[1]) != std::string_view::npos &&
         (ext[2] == 'b' || ext[2] == 'c') && ext[3] == 'd';
}

BinaryFile parse_binary_file(std::string_view raw, const std::string& source_name, const ReadOptions& options,
                             bool compressed) {
  BinaryFile file;
  file.source_ = source_name;
  file.compressed_ = compressed;
  std::string decompressed;
  std::optional<Warning> compression_damage;
  std::string_view bytes = raw;
  if (compressed) {
    if (raw.empty()) throw SlocumError(source_name, 0, "empty file");
    Decompressed plain = decompress_blocks(raw, source_name);
    decompressed = std::move(plain.bytes);
    compression_damage = std::move(plain.damage);
    bytes = decompressed;
  }
  file.decompressed_size_ = bytes.size();
  std::size_t pos = 0;
  try {
    file.header_ = detail::parse_header(bytes, pos, source_name);
    if (file.header_.sensor_list_factored) {
      file.sensors_ = detail::load_cached_list(file.header_, source_name, options);
    } else {
      const std::size_t list_start = pos;
      file.sensors_ =
          std::make_shared<const SensorList>(detail::parse_sensor_list(bytes, pos, file.header_, source_name));
      detail::store_list(file.header_, bytes.substr(list_start, pos - list_start), options);
    }
    file.binary_offset_ = pos;
    file.byte_order_ = detail::read_known_bytes(bytes, pos, source_name);
  } catch (const SlocumError& error) {
    // A header cut short by a damaged compressed block is that damage.
    if (compression_damage) throw SlocumError(source_name, compression_damage->offset, compression_damage->problem);
    throw;
  }
  const SensorList& sensors = *file.sensors_;
  const auto has = [&sensors](std::string_view name) {
    return std::any_of(sensors.begin(), sensors.end(), [name](const Sensor& s) { return s.name == name; });
  };
  file.time_variable_ = has("m_present_time") ? "m_present_time" : "sci_m_present_time";
  const std::optional<std::size_t> time_index = file.index_of(file.time_variable_);
  if (!time_index) {
    file.warnings_.push_back({source_name, 0, "neither m_present_time nor sci_m_present_time is in the sensor list"});
  }
  detail::DecodedCycles cycles = detail::decode_cycles(bytes, pos, file.header_, sensors, time_index, file.byte_order_,
                                                       options.skip_first_cycle, source_name);
  file.cycle_time_ = std::move(cycles.cycle_time);
  file.series_ = std::move(cycles.series);
  file.complete_ = cycles.complete && !compression_damage;
  if (compression_damage) {
    compression_damage->problem += " (compressed file offset; the cycles decompressed before it are kept)";
    file.warnings_.push_back(*compression_damage);
  }
  for (Warning& warning : cycles.warnings) {
    if (compressed) warning.problem += " (offset in the decompressed data)";
    file.warnings_.push_back(std::move(warning));
  }
  return file;
}

BinaryFile read_binary_file(const std::filesystem::path& path, const ReadOptions& options) {
  const std::string bytes = read_file_bytes(path);
  return parse_binary_file(bytes, path.string(), options, is_compressed_name(path));
}

TimeSeries get(const BinaryFile& file, std::string_view name, bool nmea_lat_lon) {
  TimeSeries out;
  const auto index = file.index_of(name);
  if (!index) return out;
  const SensorSeries& series = file.series()[*index];
  const std::vector<double>& cycle_time = file.cycle_time();
  const bool lat_lon = is_lat_lon_sensor(name);
  out.time.reserve(series.cycles.size());
  out.value.reserve(series.cycles.size());
  for (std::size_t k = 0; k < series.cycles.size(); ++k) {
    double v = series.values[k];
    if (lat_lon) {
      if (!is_valid_nmea(name, v)) continue;
      if (!nmea_lat_lon) v = nmea_to_decimal(v);
    }
    out.time.push_back(cycle_time[series.cycles[k]]);
    out.value.push_back(v);
  }
  return out;
}

}  // namespace glider::slocum
