// SPDX-License-Identifier: Apache-2.0
#include "glider/cli/tool.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
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
  // Hidden: the table of number options (tests/cli tries each with bad values).
  if (argc == 2 && std::string_view(argv[1]) == "--list-numeric-options") {
    std::printf("%s\n", numeric_options_json().c_str());
    return kOk;
  }
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

namespace {

// The text as a double: the whole text, an optional leading '+', "nan" and
// "inf" included (they are refused by the range, with the range named).
std::optional<double> parse_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

// A whole number in [min, max], written only with digits and a sign.
std::optional<std::int64_t> parse_integer(std::string_view text, std::int64_t min, std::int64_t max) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  if (value < min || value > max) return std::nullopt;
  return value;
}

std::string integer_range(std::int64_t min, std::int64_t max, const std::string& unit) {
  std::string out = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (!unit.empty()) out += " " + unit;
  return out;
}

std::string unit_of(const config::Range& range) { return range.unit == nullptr ? "" : range.unit; }

void collect_numeric(const CLI::App& app, const std::string& command, const std::vector<NumberOption>& numbers,
                     nlohmann::json& unregistered) {
  for (const CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    if (type != "FLOAT" && type != "INT" && type != "UINT" && type != "NUMBER") continue;
    const bool known =
        std::any_of(numbers.begin(), numbers.end(), [option](const NumberOption& n) { return n.option == option; });
    if (!known) unregistered.push_back({{"command", command}, {"name", option->get_name()}, {"type", type}});
  }
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    collect_numeric(*sub, sub->get_name(), numbers, unregistered);
  }
}

}  // namespace

NumberCheck::NumberCheck(const config::Range& range) {
  const std::string allowed = config::show_range(range);
  description("NUMBER in " + allowed);
  non_modifying();
  func_ = [range, allowed](std::string& text) -> std::string {
    const std::optional<double> value = parse_number(text);
    if (!value) return "value " + config::shorten(text) + " is not a number (allowed range " + allowed + ")";
    if (!config::within(*value, range)) {
      return "value " + config::shorten(text) + " is outside the allowed range " + allowed;
    }
    return std::string{};
  };
}

IntegerCheck::IntegerCheck(std::int64_t min, std::int64_t max, const std::string& unit) {
  const std::string allowed = integer_range(min, max, unit);
  description("INTEGER in " + allowed);
  non_modifying();
  func_ = [min, max, allowed](std::string& text) -> std::string {
    if (parse_integer(text, min, max)) return std::string{};
    return "value " + config::shorten(text) + " is not a whole number in the allowed range " + allowed;
  };
}

void Tool::record(CLI::App* command, const CLI::Option* option, NumberOption number) {
  number.option = option;
  number.command = command == &app_ ? std::string{} : command->get_name();
  numbers_.push_back(std::move(number));
}

CLI::Option* Tool::add_number(CLI::App* command, const std::string& name, double& value, const config::Range& range,
                              const std::string& help) {
  CLI::Option* option = command->add_option(name, value, help)->check(NumberCheck(range));
  record(command, option, NumberOption{option, {}, {}, false, range.min, range.max, 0, 0, unit_of(range)});
  return option;
}

CLI::Option* Tool::add_numbers(const std::string& name, std::vector<double>& values, const config::Range& range,
                               const std::string& help) {
  CLI::Option* option = app_.add_option(name, values, help)->check(NumberCheck(range));
  record(&app_, option, NumberOption{option, {}, {}, false, range.min, range.max, 0, 0, unit_of(range)});
  return option;
}

void Tool::set_leading(const CLI::Option* option, std::vector<std::string> leading) {
  for (NumberOption& number : numbers_) {
    if (number.option == option) {
      number.leading = std::move(leading);  // each option is recorded once
      return;
    }
  }
}

std::string Tool::numeric_options_json() {
  nlohmann::json options = nlohmann::json::array();
  for (const NumberOption& n : numbers_) {
    nlohmann::json entry{{"command", n.command},
                         {"name", n.option->get_name()},
                         {"positional", n.option->get_positional() && n.option->get_lnames().empty()},
                         {"leading", n.leading},
                         {"integer", n.integer},
                         {"unit", n.unit}};
    if (n.integer) {
      entry["min"] = n.integer_min;
      entry["max"] = n.integer_max;
      entry["allowed"] = integer_range(n.integer_min, n.integer_max, n.unit);
    } else {
      entry["min"] = n.min;
      entry["max"] = n.max;
      entry["allowed"] = config::show_range(config::Range{n.min, n.max, n.unit.c_str()});
    }
    options.push_back(entry);
  }
  nlohmann::json unregistered = nlohmann::json::array();
  collect_numeric(app_, "", numbers_, unregistered);
  return nlohmann::json{{"program", name_}, {"options", options}, {"unregistered", unregistered}}.dump(1);
}

}  // namespace glider::cli
