// SPDX-License-Identifier: Apache-2.0
#include "sensor_cache.hpp"

#include <array>
#include <cctype>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

#include "ascii_header.hpp"
#include "glider/slocum/lz4_blocks.hpp"

namespace glider::slocum::detail {
namespace {

namespace fs = std::filesystem;

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::vector<fs::path> search_dirs(const std::string& source, const ReadOptions& options) {
  if (!options.cache_dirs.empty()) return options.cache_dirs;
  const fs::path dir = fs::path(source).parent_path();
  const fs::path base = dir.empty() ? fs::path(".") : dir;
  return {base / "cac", base};
}

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw SlocumError(path.string(), 0, "cannot read the sensor-list cache file");
  return std::move(text).str();
}

std::optional<fs::path> find_cache_file(const std::string& crc, const std::vector<fs::path>& dirs) {
  const std::array<std::string, 8> names = {crc + ".cac", crc + ".CAC", upper(crc) + ".cac", upper(crc) + ".CAC",
                                            crc + ".ccc", crc + ".CCC", upper(crc) + ".ccc", upper(crc) + ".CCC"};
  std::error_code error;
  for (const fs::path& dir : dirs) {
    for (const std::string& name : names) {
      if (fs::is_regular_file(dir / name, error)) return dir / name;
    }
  }
  return std::nullopt;
}

}  // namespace

std::shared_ptr<const SensorList> load_cached_list(const Header& header, const std::string& source,
                                                   const ReadOptions& options) {
  const std::string& crc = header.sensor_list_crc;
  if (options.memo != nullptr) {
    const auto it = options.memo->by_crc.find(crc);
    if (it != options.memo->by_crc.end()) {
      // A list read for another file of the set: it must fit this header too
      // (a damaged header, or a CRC that does not belong to its list).
      if (it->second->size() != header.sensors_per_cycle) {
        throw SlocumError(source, 0,
                          "sensor list " + crc + " (read for another file of the set) has " +
                              std::to_string(it->second->size()) + " sensors, this header says " +
                              std::to_string(header.sensors_per_cycle) + " per cycle");
      }
      return it->second;
    }
  }
  const std::vector<fs::path> dirs = search_dirs(source, options);
  const auto path = find_cache_file(crc, dirs);
  if (!path) {
    std::string where;
    for (const fs::path& dir : dirs) where += (where.empty() ? "" : ", ") + dir.string();
    throw SlocumError(source, 0,
                      "sensor list " + crc + " is factored out (sensor_list_factored: 1) and no cache file " + crc +
                          ".cac or " + crc + ".ccc (either case) is in: " + where +
                          " (give the glider's cache directory with --cache DIR)");
  }
  std::string text = read_all(*path);
  const std::string cache_name = path->string();
  if (is_compressed_name(*path)) {
    Decompressed plain = decompress_blocks(text, cache_name);
    if (plain.damage) throw SlocumError(cache_name, plain.damage->offset, plain.damage->problem);
    text = std::move(plain.bytes);
  }
  std::size_t pos = 0;
  auto list = std::make_shared<const SensorList>(parse_sensor_list(text, pos, header, cache_name));
  if (options.memo != nullptr) options.memo->by_crc.emplace(crc, list);
  return list;
}

void store_list(const Header& header, std::string_view list_lines, const ReadOptions& options) {
  if (!options.cache_write_dir) return;
  const fs::path& dir = *options.cache_write_dir;
  if (find_cache_file(header.sensor_list_crc, {dir})) return;
  std::error_code error;
  fs::create_directories(dir, error);
  const fs::path path = dir / (header.sensor_list_crc + ".cac");
  // Written under a temporary name and renamed: a reader in parallel never
  // sees half a list.
  const fs::path partial = dir / (header.sensor_list_crc + ".cac.partial");
  {
    std::ofstream out(partial, std::ios::binary);
    out.write(list_lines.data(), static_cast<std::streamsize>(list_lines.size()));
    if (!out) throw SlocumError(path.string(), 0, "cannot write the sensor-list cache file");
  }
  fs::rename(partial, path, error);
  if (error) throw SlocumError(path.string(), 0, "cannot write the sensor-list cache file: " + error.message());
}

}  // namespace glider::slocum::detail
