// SPDX-License-Identifier: Apache-2.0
#pragma once
// A validation report: Markdown text, data files and gnuplot scripts in one
// directory; the plots are rendered by gnuplot (PNG).
#include <filesystem>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace glider::report {

class Report {
 public:
  explicit Report(std::filesystem::path directory);

  std::ostringstream& text() { return text_; }
  void table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
  // Whitespace-separated columns, one row per line, for gnuplot.
  void data(const std::string& name, const std::vector<std::string>& column_names,
            const std::vector<std::vector<double>>& columns);
  // A gnuplot script that writes `name`.png; linked into the text.
  void plot(const std::string& name, const std::string& caption, const std::string& script);

  // Writes README.md and renders the plots; false (with a message on
  // stderr) if gnuplot fails. Every file is written by write_file (throws).
  bool finish();

 private:
  std::filesystem::path directory_;
  std::ostringstream text_;
  std::vector<std::string> plots_;
};

std::string fixed(double value, int decimals);

// Writes `text` to `path` whole or not at all: into a temporary file beside
// it, checked after closing, then renamed over `path`. On failure (a full
// disk) removes the temporary file and throws std::runtime_error naming
// `path`: an empty result file must never read as a result.
void write_file(const std::filesystem::path& path, std::string_view text);

}  // namespace glider::report
