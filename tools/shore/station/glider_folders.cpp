// SPDX-License-Identifier: Apache-2.0
#include "glider_folders.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "glider/utc_time.hpp"
#include "surface_dialog.hpp"

namespace glider::shore {
namespace fs = std::filesystem;
namespace {

// flock(2) on ROOT/GLIDER/.lock for the duration of a queue change.
class FolderLock {
 public:
  explicit FolderLock(const GliderFolders& folders) {
    const std::string path = (folders.base / ".lock").string();
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0 || ::flock(fd_, LOCK_EX) != 0) throw std::runtime_error(path + ": cannot lock");
  }
  ~FolderLock() { ::close(fd_); }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

std::vector<std::string> read_lines(const fs::path& path) {
  std::vector<std::string> lines;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

void write_lines(const fs::path& path, const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  write_file_atomically(path, text);
}

}  // namespace

GliderFolders glider_folders(const fs::path& root, const std::string& glider, bool create) {
  if (!valid_glider_name(glider)) {
    throw std::runtime_error("glider name '" + glider + "': allowed are 1-32 letters, digits, '_' and '-'");
  }
  GliderFolders f;
  f.base = root / glider;
  f.from_glider = f.base / "from-glider";
  f.to_glider = f.base / "to-glider";
  f.sent = f.to_glider / "sent";
  f.logs = f.base / "logs";
  f.incoming = f.base / ".incoming";
  f.commands = f.base / "commands.queue";
  if (create) {
    for (const fs::path& dir : {f.from_glider, f.sent, f.logs, f.incoming}) fs::create_directories(dir);
  }
  return f;
}

void write_file_atomically(const fs::path& target, const std::string& content) {
  // Hidden and suffixed: never taken for a published file (queued_files skips dot names).
  std::string temp_name = ".";
  temp_name += target.filename().string();
  temp_name += ".tmp";
  const fs::path temp = target.parent_path() / temp_name;
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(temp.string() + ": cannot write");
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n <= 0) {
      ::close(fd);
      throw std::runtime_error(temp.string() + ": write error");
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) throw std::runtime_error(temp.string() + ": write error");
  fs::rename(temp, target);
}

void copy_file_atomically(const fs::path& source, const fs::path& target) {
  std::ifstream in(source, std::ios::binary);
  if (!in) throw std::runtime_error(source.string() + ": cannot read");
  std::ostringstream content;
  content << in.rdbuf();
  write_file_atomically(target, content.str());
}

void queue_command(const GliderFolders& folders, const std::string& command) {
  if (command.empty() || command.find_first_of("\r\n") != std::string::npos) {
    throw std::runtime_error("command '" + command + "': one non-empty line expected");
  }
  FolderLock lock(folders);
  std::vector<std::string> lines = read_lines(folders.commands);
  lines.push_back(command);
  write_lines(folders.commands, lines);
}

std::vector<std::string> queued_commands(const GliderFolders& folders) {
  FolderLock lock(folders);
  return read_lines(folders.commands);
}

void drop_first_command(const GliderFolders& folders, const std::string& command) {
  FolderLock lock(folders);
  std::vector<std::string> lines = read_lines(folders.commands);
  if (lines.empty() || lines.front() != command) return;
  lines.erase(lines.begin());
  write_lines(folders.commands, lines);
}

std::vector<fs::path> queued_files(const GliderFolders& folders) {
  std::vector<fs::path> files;
  if (!fs::is_directory(folders.to_glider)) return files;
  for (const fs::directory_entry& entry : fs::directory_iterator(folders.to_glider)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && !name.empty() && name[0] != '.') files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

double now_unix() { return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count(); }

std::string utc_iso(double unix_seconds) { return utc::format_iso(unix_seconds); }
std::string utc_stamp(double unix_seconds) { return utc::format_compact(unix_seconds); }

}  // namespace glider::shore

namespace glider::shore {
bool remove_command(const GliderFolders& folders, std::size_t index, const std::string& command) {
  FolderLock lock(folders);
  std::vector<std::string> lines = read_lines(folders.commands);
  if (index >= lines.size() || lines[index] != command) return false;
  lines.erase(lines.begin() + static_cast<long>(index));
  write_lines(folders.commands, lines);
  return true;
}
}  // namespace glider::shore
