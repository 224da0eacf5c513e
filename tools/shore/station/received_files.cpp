// SPDX-License-Identifier: Apache-2.0
#include "received_files.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "glider/slocum/csv_export.hpp"
#include "glider/slocum/deployment.hpp"

namespace glider::shore {
namespace fs = std::filesystem;
namespace {

bool same_bytes(const fs::path& a, const fs::path& b) {
  if (fs::file_size(a) != fs::file_size(b)) return false;
  std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
  return std::equal(std::istreambuf_iterator<char>(fa), std::istreambuf_iterator<char>(),
                    std::istreambuf_iterator<char>(fb));
}

void convert_to_csv(const GliderFolders& folders, const fs::path& data, const std::vector<fs::path>& cache_dirs,
                    ReceivedFile& record) {
  try {
    glider::slocum::DeploymentOptions options;
    options.read.cache_dirs = {folders.from_glider, folders.from_glider / "cac"};
    for (const fs::path& dir : cache_dirs) options.read.cache_dirs.push_back(dir);
    // A file that carries its own sensor list leaves it for the later factored ones.
    fs::create_directories(folders.from_glider / "cac");
    options.read.cache_write_dir = folders.from_glider / "cac";
    const glider::slocum::Deployment deployment = glider::slocum::read_deployment({data}, options);
    std::ostringstream csv;
    glider::slocum::write_csv(deployment, csv);
    const fs::path target = data.parent_path() / (data.filename().string() + ".csv");
    write_file_atomically(target, csv.str());
    record.csv = target.filename().string();
  } catch (const std::exception& error) {
    record.csv_error = error.what();
  }
}

}  // namespace

bool is_slocum_data_file(const fs::path& path) {
  static const std::vector<std::string> kinds = {".sbd", ".tbd", ".dbd", ".ebd", ".mbd", ".nbd",
                                                 ".scd", ".tcd", ".dcd", ".ecd", ".mcd", ".ncd"};
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return std::find(kinds.begin(), kinds.end(), ext) != kinds.end();
}

ReceivedFile publish_received(const GliderFolders& folders, const std::string& name,
                              const std::vector<fs::path>& cache_dirs) {
  // rz names files from the glider's ZFILE header: refuse anything that is not a plain name.
  if (name.empty() || name[0] == '.' || name.find('/') != std::string::npos) {
    throw std::runtime_error("received file name '" + name + "' is not a plain file name");
  }
  const fs::path source = folders.incoming / name;
  const fs::path target = folders.from_glider / name;
  ReceivedFile record;
  record.name = name;
  record.bytes = fs::file_size(source);
  if (fs::exists(target) && same_bytes(source, target)) {
    fs::remove(source);
    record.status = "duplicate";
    return record;
  }
  record.status = fs::exists(target) ? "replaced" : "new";
  fs::rename(source, target);
  if (is_slocum_data_file(target)) convert_to_csv(folders, target, cache_dirs, record);
  return record;
}

std::vector<std::string> partial_receptions(const GliderFolders& folders) {
  std::vector<std::string> names;
  if (!fs::is_directory(folders.incoming)) return names;
  for (const fs::directory_entry& entry : fs::directory_iterator(folders.incoming)) {
    if (entry.is_regular_file()) names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace glider::shore
