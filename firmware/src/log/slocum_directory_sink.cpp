// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/log/slocum_directory_sink.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <lz4.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "glider/firmware/log/slocum_format.hpp"

namespace glider::fw {
namespace {

bool make_directory(const std::string& path, std::string& error) {
  // Each component in turn (mkdir -p).
  for (std::size_t at = 1; at <= path.size(); ++at) {
    if (at != path.size() && path[at] != '/') continue;
    const std::string part = path.substr(0, at);
    if (::mkdir(part.c_str(), 0755) != 0 && errno != EEXIST) {
      error = part + ": cannot create the Slocum data directory: " + std::strerror(errno);
      return false;
    }
  }
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)) {
    error = path + ": is not a directory";
    return false;
  }
  return true;
}

// The 8.3 mission number in the header of the file at `path` (the first
// four digits of the8x3_filename), -1 if none; an LZ4 form (.?cd) is read
// through its first block.
long eight_three_mission(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) return -1;
  std::string raw(std::size_t{64} * 1024 + 2, '\0');
  raw.resize(std::fread(raw.data(), 1, raw.size(), file));
  std::fclose(file);
  std::string header = raw.substr(0, 1024);
  if (path.size() > 4 && path.compare(path.size() - 2, 2, "cd") == 0 && raw.size() > 2) {
    const std::size_t block =
        (static_cast<std::size_t>(static_cast<unsigned char>(raw[0])) << 8) | static_cast<unsigned char>(raw[1]);
    header.assign(1024, '\0');
    const int n = LZ4_decompress_safe_partial(raw.data() + 2, header.data(),
                                              static_cast<int>(std::min(block, raw.size() - 2)), 1024, 1024);
    header.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  }
  constexpr std::string_view kKey = "\nthe8x3_filename:";
  const std::size_t at = header.find(kKey);
  if (at == std::string::npos) return -1;
  return std::strtol(header.c_str() + at + kKey.size(), nullptr, 10) / 10000;
}

}  // namespace

SlocumDirectorySink::SlocumDirectorySink(const std::string& directory)
    : directory_(directory.empty() ? std::string(".") : directory) {
  fd_.fill(-1);
  if (directory_.size() + 64 > path_.size()) {
    error_ = directory_ + ": the Slocum data directory's path is too long";
    return;
  }
  if (make_directory(directory_, error_)) make_directory(directory_ + "/cac", error_);
}

SlocumDirectorySink::~SlocumDirectorySink() {
  for (int slot = 0; slot < kSlots; ++slot) close(slot);
}

bool SlocumDirectorySink::open(int slot, const char* name) {
  if (slot < 0 || slot >= kSlots) return false;
  const auto s = static_cast<std::size_t>(slot);
  if (fd_[s] >= 0) close(slot);
  const int n = std::snprintf(path_.data(), path_.size(), "%s/%s", directory_.c_str(), name);
  if (n <= 0 || static_cast<std::size_t>(n) >= path_.size()) return false;
  fd_[s] = ::open(path_.data(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  length_[s] = 0;
  {
    const std::lock_guard<std::mutex> lock(names_mutex_);
    std::snprintf(open_name_[s].data(), open_name_[s].size(), "%s", fd_[s] >= 0 ? name : "");
  }
  return fd_[s] >= 0;
}

bool SlocumDirectorySink::write(int slot, const char* data, std::size_t size) {
  if (slot < 0 || slot >= kSlots || fd_[static_cast<std::size_t>(slot)] < 0) return false;
  const auto s = static_cast<std::size_t>(slot);
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd_[s], data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      // Nothing of this buffer stays: the file ends at its last whole one.
      if (::ftruncate(fd_[s], static_cast<off_t>(length_[s])) != 0) {
        ::close(fd_[s]);  // cannot cut it back: stop writing this file
        fd_[s] = -1;
      }
      ++write_failures_;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  length_[s] += size;
  return true;
}

bool SlocumDirectorySink::is_open(const char* name) const {
  const std::lock_guard<std::mutex> lock(names_mutex_);
  for (const auto& open : open_name_) {
    if (open[0] != '\0' && std::strcmp(open.data(), name) == 0) return true;
  }
  return false;
}

bool SlocumDirectorySink::close(int slot) {
  if (slot < 0 || slot >= kSlots) return false;
  const auto s = static_cast<std::size_t>(slot);
  if (fd_[s] < 0) return false;
  {
    const std::lock_guard<std::mutex> lock(names_mutex_);
    open_name_[s][0] = '\0';
  }
  const bool synced = ::fsync(fd_[s]) == 0;
  const bool closed = ::close(fd_[s]) == 0;
  fd_[s] = -1;
  return synced && closed;
}

SlocumMissionNumbers next_slocum_mission(const std::string& directory, const std::string& vehicle,
                                         hal::Micros start_utc_us) {
  SlocumMissionNumbers next;
  const UtcDate date = utc_date(start_utc_us);
  char day_prefix[96];
  std::snprintf(day_prefix, sizeof day_prefix, "%s-%04d-%03d-", vehicle.c_str(), date.year, date.day_of_year);
  const std::string vehicle_prefix = vehicle + "-";
  // The folder, and sentlogs/ where the comms move the files the shore has.
  for (const std::string& folder : {directory, directory + "/sentlogs"}) {
    DIR* dir = ::opendir(folder.c_str());
    if (dir == nullptr) continue;
    while (const dirent* entry = ::readdir(dir)) {
      const std::string_view name(entry->d_name);
      if (!name.starts_with(vehicle_prefix)) continue;
      if (name.starts_with(day_prefix)) {
        const int mission = std::atoi(name.substr(std::strlen(day_prefix)).data());
        if (mission + 1 > next.mission_of_day) next.mission_of_day = mission + 1;
      }
      const long number = eight_three_mission(folder + "/" + std::string(name));
      if (number + 1 > next.mission_number) next.mission_number = static_cast<int>(number + 1);
    }
    ::closedir(dir);
  }
  return next;
}

}  // namespace glider::fw
