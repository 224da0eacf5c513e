// SPDX-License-Identifier: Apache-2.0
#include "session_journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <stdexcept>

#include "glider/utc_time.hpp"

namespace glider::shore {
namespace {

std::string timestamp_now() {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return utc::format_iso(std::chrono::duration<double>(now).count(), 3);
}

}  // namespace

std::string escape_bytes(const std::string& bytes) {
  std::string out;
  out.reserve(bytes.size());
  for (const char c : bytes) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte == '\\') {
      out += "\\\\";
    } else if (byte >= 0x20 && byte < 0x7f) {
      out += c;
    } else {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02X", byte);
      out += hex;
    }
  }
  return out;
}

namespace {

std::string journal_line(char direction, const std::string& text) {
  return timestamp_now() + " " + direction + " " + escape_bytes(text);
}

}  // namespace

void SessionJournal::write(char direction, const std::string& text) {
  std::string line = journal_line(direction, text);
  if (out_.is_open()) {
    out_ << line << '\n';
    out_.flush();  // a journal is read while the call goes on (tail -f)
  } else {
    held_.push_back(std::move(line));
  }
}

void SessionJournal::open(const std::filesystem::path& path) {
  out_.open(path, std::ios::app);
  if (!out_) throw std::runtime_error(path.string() + ": cannot write the journal");
  path_ = path;
  for (const std::string& line : held_) out_ << line << '\n';
  held_.clear();
  out_.flush();
}

void SessionJournal::append(const std::filesystem::path& path, char direction, const std::string& text) {
  std::ofstream out(path, std::ios::app);
  out << journal_line(direction, text) << '\n';
  out.flush();
  if (!out) throw std::runtime_error(path.string() + ": cannot append to the journal");
}

std::string SessionJournal::open_new(const std::filesystem::path& dir, const std::string& stamp, unsigned first) {
  for (unsigned n = first; n < first + 10000; ++n) {
    char id[64];
    std::snprintf(id, sizeof id, "%s_%04u", stamp.c_str(), n % 10000);
    const std::filesystem::path path = dir / (std::string(id) + ".journal");
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0 && errno == EEXIST) continue;
    if (fd < 0) throw std::runtime_error(path.string() + ": cannot create the journal: " + std::strerror(errno));
    ::close(fd);
    open(path);
    return id;
  }
  throw std::runtime_error(dir.string() + ": 10000 journals named " + stamp + "_NNNN already: none free");
}

}  // namespace glider::shore
