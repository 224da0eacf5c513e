// SPDX-License-Identifier: Apache-2.0
// glider-convert: Slocum binary files (.dbd/.ebd/... and LZ4 .dcd/.ecd/...,
// a directory, glob or list) -> one flight-log CSV (docs/flight-log.md), as
// the real-data CSVs in tests/data/real were made (docs/slocum-binary.md).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/slocum/csv_export.hpp"
#include "glider/slocum/deployment.hpp"

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-convert",
                         "Slocum binary files (dbd/ebd/sbd/tbd/mbd/nbd, LZ4 dcd/ecd/...) -> flight-log CSV");
  std::vector<std::string> inputs;
  std::vector<std::string> cache_dirs;
  std::string columns;
  std::string out_path;
  std::string write_cache;
  bool quiet = false;
  CLI::App& app = tool.app();
  app.add_option("FILES", inputs, "data files, directories or glob patterns (read in segment order)")->required();
  app.add_option("--cache", cache_dirs,
                 "directory of the sensor-list caches <crc>.cac/.ccc (repeatable; default: each file's folder and "
                 "its cac/)")
      // One directory per --cache, so the files after it are not taken as more cache directories (the
      // documented order `--cache DIR --columns ... FILE... --out LOG.csv`).
      ->allow_extra_args(false);
  app.add_option("--write-cache", write_cache, "store the sensor lists of files that carry their own here");
  app.add_option("--columns", columns, "only these columns, comma separated (default: every sensor with a value)");
  app.add_option("--out", out_path, "CSV file to write")->required();
  app.add_flag("--quiet", quiet, "do not print warnings (damaged or skipped files, dropped values)");
  return tool.run(argc, argv, [&] {
    glider::slocum::DeploymentOptions options;
    for (const std::string& dir : cache_dirs) options.read.cache_dirs.emplace_back(dir);
    if (!write_cache.empty()) options.read.cache_write_dir = write_cache;
    for (std::size_t start = 0; !columns.empty() && start <= columns.size();) {
      const std::size_t comma = columns.find(',', start);
      const std::string name = columns.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      if (!name.empty()) options.columns.push_back(name);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    const glider::slocum::Deployment deployment =
        glider::slocum::read_deployment(glider::slocum::deployment_files(inputs), options);
    if (!quiet) {
      for (const auto& warning : deployment.warnings) std::fprintf(stderr, "warning: %s\n", warning.text().c_str());
    }
    std::ofstream out(out_path, std::ios::binary);
    if (!out) throw std::runtime_error(out_path + ": cannot write");
    glider::slocum::write_csv(deployment, out);
    out.close();
    if (!out) throw std::runtime_error(out_path + ": write error");
    std::fprintf(stderr, "%s: %zu rows x %zu columns from %zu files\n", out_path.c_str(), deployment.log.rows(),
                 deployment.log.column_names().size(), deployment.files.size());
    return glider::cli::kOk;
  });
}
