// SPDX-License-Identifier: Apache-2.0
// glider-convert: Slocum binary files (.dbd/.ebd/... and LZ4 .dcd/.ecd/...,
// a directory, glob or list) -> one flight-log CSV (docs/flight-log.md), as
// the real-data CSVs in tests/data/real were made (docs/slocum-binary.md);
// or, with --format og1|ioos, the community NetCDF files (docs/netcdf.md).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/slocum/csv_export.hpp"
#include "glider/slocum/deployment.hpp"
#include "netcdf_output.hpp"

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-convert",
                         "Slocum binary files (dbd/ebd/sbd/tbd/mbd/nbd, LZ4 dcd/ecd/...) -> flight-log CSV");
  std::vector<std::string> inputs;
  std::vector<std::string> cache_dirs;
  std::string columns;
  std::string out_path;
  std::string write_cache;
  bool quiet = false;
  glider::convert::NetcdfRequest netcdf;
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
  app.add_option("--out", out_path, "file to write (CSV, OG1.0 .nc), or the directory of the IOOS profile files")
      ->required();
  app.add_option("--format", netcdf.format, "csv (default), og1 (OceanGliders 1.0) or ioos (IOOS NGDAC v2)")
      ->check(CLI::IsMember({"csv", "og1", "ioos"}));
  app.add_option("--metadata", netcdf.metadata, "deployment metadata TOML (required by og1 and ioos)");
  app.add_option("--vehicle", netcdf.vehicle, "vehicle file: adds the flight model's products (og1, ioos)");
  app.add_flag("--quiet", quiet, "do not print warnings (damaged or skipped files, dropped values)");
  return tool.run(argc, argv, [&]() -> int {
    glider::slocum::DeploymentOptions options;
    for (const std::string& dir : cache_dirs) options.read.cache_dirs.emplace_back(dir);
    if (!write_cache.empty()) options.read.cache_write_dir = write_cache;
    if (netcdf.format != "csv") {
      if (netcdf.metadata.empty()) {
        throw glider::cli::ToolError(glider::cli::kUsage, "--format " + netcdf.format + " needs --metadata FILE");
      }
      if (columns.empty()) {
        options.columns = glider::convert::netcdf_columns();
        options.skip_missing_columns = true;
      }
    } else if (!netcdf.metadata.empty() || !netcdf.vehicle.empty()) {
      throw glider::cli::ToolError(glider::cli::kUsage, "--metadata and --vehicle are for --format og1|ioos");
    }
    netcdf.command_line = glider::convert::command_line(argc, argv);
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
#ifdef GLIDER_CONVERT_NETCDF
    if (netcdf.format != "csv") return glider::convert::write_netcdf(deployment, netcdf, out_path);
#else
    if (netcdf.format != "csv") throw std::runtime_error("this build has no NetCDF library: --format csv only");
#endif
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
