// SPDX-License-Identifier: Apache-2.0
#pragma once
// One glider's folders under the shore root (docs/comms.md, "Shore station"):
//
//   ROOT/GLIDER/from-glider/   files received from the glider (+ NAME.csv conversions)
//   ROOT/GLIDER/to-glider/     files queued for the next call (sent ones move to to-glider/sent/)
//   ROOT/GLIDER/logs/          session journals and surfacing events
//   ROOT/GLIDER/commands.queue console commands queued for the next call, one a line
//   ROOT/GLIDER/.incoming/     Zmodem receptions in progress (kept for resume, never published)
//
// Everything a reader may see appears by rename(2) of a complete file, so a
// reader never sees a partial one.
#include <filesystem>
#include <string>
#include <vector>

namespace glider::shore {

struct GliderFolders {
  std::filesystem::path base, from_glider, to_glider, sent, logs, incoming, commands;
};

// The folders of GLIDER under root (name checked with valid_glider_name); created when `create`.
GliderFolders glider_folders(const std::filesystem::path& root, const std::string& glider, bool create);

// Writes `content` to a hidden temporary beside `target`, fsyncs and renames it over `target`.
void write_file_atomically(const std::filesystem::path& target, const std::string& content);
// Copies `source` to `target` the same way.
void copy_file_atomically(const std::filesystem::path& source, const std::filesystem::path& target);

// Queued console commands (commands.queue), under an exclusive lock so the
// daemon and `glider-shore queue` never lose one.
void queue_command(const GliderFolders& folders, const std::string& command);
std::vector<std::string> queued_commands(const GliderFolders& folders);
// Removes the first queued command if it is `command` (it has been sent).
void drop_first_command(const GliderFolders& folders, const std::string& command);

// Regular, non-hidden files of to-glider/, by name.
std::vector<std::filesystem::path> queued_files(const GliderFolders& folders);

// "2026-11-27T05:40:12Z" and "20261127T054012" for a unix time.
std::string utc_iso(double unix_seconds);
std::string utc_stamp(double unix_seconds);
double now_unix();

}  // namespace glider::shore

namespace glider::shore {
// Removes the queued command at `index` if it is still `command` (the console's cancel); false otherwise.
bool remove_command(const GliderFolders& folders, std::size_t index, const std::string& command);
}  // namespace glider::shore
