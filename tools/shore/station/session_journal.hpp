// SPDX-License-Identifier: Apache-2.0
#pragma once
// The journal of one call: every line both ways, one journal line each
// (docs/comms.md, "Journal format"):
//
//   2026-11-27T05:40:12.345Z < GPS Location:  4319.400 N 00726.900 E measured  12.0 secs ago
//   2026-11-27T05:40:13.002Z > whoru
//   2026-11-27T05:40:20.117Z * zmodem receive: 2 files, 61440 bytes in, exit 0
//
// '<' glider to shore, '>' shore to glider, '*' the shore's own note. Bytes
// that are not printable ASCII are written as \xNN (a backslash as \\), so a
// journal is one text line per event whatever the link carried. Until the
// glider is identified the lines are held in memory, then written to the
// glider's logs/ (or to ROOT/unidentified/ when it never says its name).
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace glider::shore {

class SessionJournal {
 public:
  void write(char direction, const std::string& text);
  // From now on lines go to `path` (the held lines first).
  void open(const std::filesystem::path& path);
  // Claims `dir`/ID.journal for a new call and opens it: ID is `stamp`_NNNN
  // with the first NNNN from `first` whose journal does not exist yet,
  // created exclusively, so a restarted shore (its call counter back at 1)
  // or a second shore on the same root never appends to, or overwrites the
  // event of, an earlier call made in the same second. Returns ID.
  std::string open_new(const std::filesystem::path& dir, const std::string& stamp, unsigned first);
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  // One line appended to an existing journal by someone other than its call
  // (the after-surfacing work, which may end after the call has).
  static void append(const std::filesystem::path& path, char direction, const std::string& text);

 private:
  std::vector<std::string> held_;
  std::ofstream out_;
  std::filesystem::path path_;
};

// Printable ASCII kept, anything else as \xNN, backslash as \\.
std::string escape_bytes(const std::string& bytes);

}  // namespace glider::shore
