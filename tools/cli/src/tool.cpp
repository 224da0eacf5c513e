// SPDX-License-Identifier: Apache-2.0
#include "glider/cli/tool.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

namespace glider::cli {

namespace {

bool has_vehicles(const std::filesystem::path& boards) {
  std::error_code ignored;
  return std::filesystem::is_directory(boards / "vehicles", ignored);
}

}  // namespace

std::string boards_dir() {
  if (const char* env = std::getenv("GLIDER_BOARDS_DIR"); env != nullptr && *env != '\0') return env;
  const std::filesystem::path source = std::filesystem::path(GLIDER_SOURCE_BOARDS_DIR);
  if (has_vehicles(source)) return source.string();
  return "/usr/share/glider/boards";
}

std::string default_vehicle_path() {
  return (std::filesystem::path(boards_dir()) / "vehicles/slocum_we01.toml").string();
}

Tool::Tool(std::string name, const std::string& description) : name_(std::move(name)), app_(description, name_) {}

CLI::Option* Tool::add_vehicle_option(std::string& path) {
  if (path.empty()) path = default_vehicle_path();
  return app_.add_option("--vehicle", path, "vehicle parameter file (TOML)")
      ->check(CLI::ExistingFile)
      ->capture_default_str();
}

CLI::Option* Tool::add_json_flag(bool& json) {
  json_ = &json;
  return app_.add_flag("--json", json, "machine-readable output: one JSON object on stdout (errors too)");
}

int Tool::fail(ExitCode code, const std::string& message) const {
  if (json_ != nullptr && *json_) {
    std::printf("%s\n", nlohmann::json{{"error", message}, {"exit_code", static_cast<int>(code)}}.dump().c_str());
  } else {
    std::fprintf(stderr, "%s: %s\n", name_.c_str(), message.c_str());
  }
  return code;
}

int Tool::run(int argc, char** argv, const std::function<int()>& body) {
  try {
    app_.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app_.exit(help) == 0 ? kOk : kUsage;
  } catch (const CLI::CallForAllHelp& help) {
    return app_.exit(help) == 0 ? kOk : kUsage;
  } catch (const CLI::CallForVersion& version) {
    return app_.exit(version) == 0 ? kOk : kUsage;
  } catch (const CLI::ParseError& error) {
    app_.exit(error);  // CLI11's own message and the hint to --help
    return kUsage;
  }
  try {
    return body();
  } catch (const ToolError& error) {
    return fail(error.code(), error.what());
  } catch (const std::exception& error) {
    return fail(kError, error.what());
  }
}

FiniteRange::FiniteRange(double min, double max) {
  description("FINITE in [" + std::to_string(min) + " - " + std::to_string(max) + "]");
  func_ = [min, max](const std::string& text) -> std::string {
    double value = 0.0;
    if (!CLI::detail::lexical_cast(text, value)) return "Value " + text + " is not a number";
    if (!std::isfinite(value) || value < min || value > max) {
      return "Value " + text + " not a finite number in range " + std::to_string(min) + " to " + std::to_string(max);
    }
    return std::string{};
  };
}

}  // namespace glider::cli
