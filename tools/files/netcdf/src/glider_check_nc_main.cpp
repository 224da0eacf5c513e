// SPDX-License-Identifier: Apache-2.0
// glider-check-nc: a NetCDF file against the required elements of OG1.0 or
// IOOS NGDAC v2 (format_rules.cpp, cited there and in docs/netcdf.md).
// Exit 0: every rule holds; 1: findings, or a file that is not NetCDF; 2: usage.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/netcdf/checker.hpp"

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-check-nc", "NetCDF files against the OG1.0 / IOOS NGDAC v2 rule table");
  std::vector<std::string> files;
  std::string format;
  bool rules = false;
  CLI::App& app = tool.app();
  app.add_option("FILES", files, "NetCDF files to check");
  app.add_option("--format", format, "check as this format instead of the one the file declares")
      ->check(CLI::IsMember({"og1", "ioos"}));
  app.add_flag("--rules", rules, "print the rule table (Markdown) and exit");
  return tool.run(argc, argv, [&] {
    using namespace glider::netcdf;
    if (rules) {
      std::printf("| id | format | element | requirement | source |\n|---|---|---|---|---|\n");
      for (const Rule& r : format_rules()) {
        std::string element = r.variable;
        if (r.attribute[0] != '\0') element += (element.empty() ? "" : ": ") + std::string(r.attribute);
        if (r.expected[0] != '\0') element += " = " + std::string(r.expected);
        std::printf("| %s | %s | %s | %s | %s |\n", r.id, std::string(to_string(r.format)).c_str(), element.c_str(),
                    r.requirement, r.source);
      }
      return glider::cli::kOk;
    }
    if (files.empty()) throw glider::cli::ToolError(glider::cli::kUsage, "no file given (FILES or --rules)");
    std::optional<Format> forced;
    if (format == "og1") forced = Format::kOg1;
    if (format == "ioos") forced = Format::kIoos;
    bool all_ok = true;
    for (const std::string& file : files) {
      const CheckResult result = check_file(file, forced);
      for (const Finding& f : result.findings) {
        std::printf("%s: %s: %s%s%s\n", file.c_str(), f.rule ? f.rule->id : "format", f.message.c_str(),
                    f.rule ? " -- " : "", f.rule ? f.rule->source : "");
      }
      std::printf("%s: %s: %zu rules checked, %zu finding(s)\n", file.c_str(),
                  result.format ? std::string(to_string(*result.format)).c_str() : "unknown format",
                  result.rules_checked, result.findings.size());
      all_ok = all_ok && result.ok();
    }
    return all_ok ? glider::cli::kOk : glider::cli::kError;
  });
}
