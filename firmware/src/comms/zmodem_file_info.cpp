// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/comms/zmodem_file_info.hpp"

#include <charconv>
#include <cstring>

namespace glider::fw::comms::zmodem {
namespace {

// Reads one unsigned number in `base` at text[pos] (after blanks); -1 if none.
std::int64_t read_number(std::string_view text, std::size_t& pos, int base) {
  while (pos < text.size() && text[pos] == ' ') ++pos;
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data() + pos, text.data() + text.size(), value, base);
  if (error != std::errc() || value < 0) return -1;
  pos = static_cast<std::size_t>(end - text.data());
  return value;
}

}  // namespace

bool is_safe_name(std::string_view name) {
  if (name.empty() || name.size() > kMaxName || name.front() == '.') return false;
  for (const char c : name) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
    if (!ok) return false;
  }
  return true;
}

bool parse_file_info(std::span<const std::uint8_t> data, FileInfo& info) {
  const std::string_view text(reinterpret_cast<const char*>(data.data()), data.size());
  const std::size_t name_end = text.find('\0');
  if (name_end == std::string_view::npos) return false;
  const std::string_view name = text.substr(0, name_end);
  if (!is_safe_name(name)) return false;
  std::memcpy(info.name.data(), name.data(), name.size());
  info.name[name.size()] = '\0';
  info.name_length = name.size();
  std::string_view rest = text.substr(name_end + 1);
  rest = rest.substr(0, rest.find('\0'));
  std::size_t pos = 0;
  info.length = read_number(rest, pos, 10);
  info.mtime = info.length < 0 ? 0 : read_number(rest, pos, 8);
  if (info.mtime < 0) info.mtime = 0;
  return true;
}

std::size_t format_file_info(const FileInfo& info, int files_left, std::int64_t bytes_left,
                             std::span<std::uint8_t> out) {
  std::array<char, 160> text{};
  std::size_t pos = 0;
  const auto put_text = [&](std::string_view s) {
    if (pos + s.size() > text.size()) return false;
    std::memcpy(text.data() + pos, s.data(), s.size());
    pos += s.size();
    return true;
  };
  const auto put_number = [&](std::int64_t value, int base) {
    const auto [end, error] = std::to_chars(text.data() + pos, text.data() + text.size(), value, base);
    if (error != std::errc()) return false;
    pos = static_cast<std::size_t>(end - text.data());
    return true;
  };
  // Mode 0100644: a regular file, rw-r--r-- (lrzsz applies it to the file it writes).
  const bool ok = put_text(info.name_view()) && put_text(std::string_view("\0", 1)) && put_number(info.length, 10) &&
                  put_text(" ") && put_number(info.mtime, 8) && put_text(" 100644 0 ") && put_number(files_left, 10) &&
                  put_text(" ") && put_number(bytes_left, 10) && put_text(std::string_view("\0", 1));
  if (!ok || pos > out.size()) return 0;
  std::memcpy(out.data(), text.data(), pos);
  return pos;
}

const char* failure_name(Failure failure) {
  switch (failure) {
    case Failure::none:
      return "none";
    case Failure::timeout:
      return "timeout";
    case Failure::cancelled:
      return "cancelled";
    case Failure::file_error:
      return "file error";
    case Failure::refused:
      return "refused";
    case Failure::too_many_errors:
      return "too many errors";
  }
  return "unknown";
}

}  // namespace glider::fw::comms::zmodem
