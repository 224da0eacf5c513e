// SPDX-License-Identifier: Apache-2.0
#include "glider/config/toml_document.hpp"

#include <algorithm>

#include <toml++/toml.h>
#include <cmath>
#include <limits>
#include <sstream>

namespace glider::config {

struct TomlDocument::Impl {
  toml::table table;
};

namespace {

std::string location(const std::string& source, const toml::source_region& region) {
  std::ostringstream out;
  out << source;
  if (region.begin.line > 0) {
    out << ':' << region.begin.line << ':' << region.begin.column;
  }
  return out.str();
}

void collect_leaves(const toml::table& table, const std::string& prefix,
                    std::vector<std::pair<std::string, toml::source_region>>& out) {
  for (const auto& [key, node] : table) {
    const std::string name = prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    if (const toml::table* sub = node.as_table()) {
      collect_leaves(*sub, name, out);
    } else {
      out.emplace_back(name, node.source());
    }
  }
}

}  // namespace

TomlDocument::TomlDocument(std::unique_ptr<Impl> impl, std::string source)
    : impl_(std::move(impl)), source_(std::move(source)) {}
TomlDocument::TomlDocument(TomlDocument&&) noexcept = default;
TomlDocument& TomlDocument::operator=(TomlDocument&&) noexcept = default;
TomlDocument::~TomlDocument() = default;

TomlDocument TomlDocument::load(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    // A FIFO or device would block the read or never end: refused by name.
    throw ConfigError(path.string() + (std::filesystem::exists(path, ec) ? ": not a regular file" : ": no such file"));
  }
  try {
    auto impl = std::make_unique<Impl>();
    impl->table = toml::parse_file(path.string());
    return TomlDocument(std::move(impl), path.string());
  } catch (const toml::parse_error& error) {
    throw ConfigError(location(path.string(), error.source()) + ": " + shorten(error.description(), 200));
  }
}

TomlDocument TomlDocument::parse(std::string_view text, const std::string& source_name) {
  try {
    auto impl = std::make_unique<Impl>();
    impl->table = toml::parse(text, source_name);
    return TomlDocument(std::move(impl), source_name);
  } catch (const toml::parse_error& error) {
    throw ConfigError(location(source_name, error.source()) + ": " + shorten(error.description(), 200));
  }
}

std::string TomlDocument::where(std::string_view dotted_key) const {
  const auto node = impl_->table.at_path(dotted_key);
  return node ? location(source_, node.node()->source()) : source_;
}

void TomlDocument::fail(std::string_view dotted_key, const std::string& message) const {
  throw ConfigError(where(dotted_key) + ": " + std::string(dotted_key) + ": " + message);
}

bool TomlDocument::has(std::string_view dotted_key) const {
  return static_cast<bool>(impl_->table.at_path(dotted_key));
}

double TomlDocument::raw_number(std::string_view dotted_key) const {
  const auto node = impl_->table.at_path(dotted_key);
  if (!node) {
    throw ConfigError(source_ + ": missing required key '" + std::string(dotted_key) + "'");
  }
  used_.emplace(dotted_key);
  std::optional<double> value = node.value<double>();  // accepts integers too
  if (!value || !node.is_number()) {
    fail(dotted_key, "expected a number");
  }
  return *value;
}

double TomlDocument::number(std::string_view dotted_key) const {
  const double value = raw_number(dotted_key);
  if (!std::isfinite(value)) {
    fail(dotted_key, "value " + show_value(value) + " is not a finite number");
  }
  return value;
}

double TomlDocument::number_or(std::string_view dotted_key, double fallback) const {
  return has(dotted_key) ? number(dotted_key) : fallback;
}

std::int64_t TomlDocument::integer(std::string_view dotted_key) const {
  const auto node = impl_->table.at_path(dotted_key);
  if (!node) {
    throw ConfigError(source_ + ": missing required key '" + std::string(dotted_key) + "'");
  }
  used_.emplace(dotted_key);
  if (!node.is_integer()) {
    fail(dotted_key, "expected an integer");
  }
  return *node.value<std::int64_t>();
}

std::int64_t TomlDocument::integer_or(std::string_view dotted_key, std::int64_t fallback) const {
  return has(dotted_key) ? integer(dotted_key) : fallback;
}

double TomlDocument::number(std::string_view dotted_key, const Range& range) const {
  const double value = raw_number(dotted_key);
  if (!within(value, range)) fail(dotted_key, range_problem(value, range));
  return value;
}

double TomlDocument::number_or(std::string_view dotted_key, double fallback, const Range& range) const {
  return has(dotted_key) ? number(dotted_key, range) : fallback;
}

std::int64_t TomlDocument::integer(std::string_view dotted_key, std::int64_t min, std::int64_t max) const {
  std::string range = "[";
  range.append(std::to_string(min)).append(", ").append(std::to_string(max)).append("]");
  const auto node = impl_->table.at_path(dotted_key);
  if (node && !node.is_integer()) {
    used_.emplace(dotted_key);
    const std::optional<double> number = node.value<double>();
    std::string message = number ? "value " + show_value(*number) : std::string("the value");
    fail(dotted_key, message.append(" is not a whole number in the allowed range ").append(range));
  }
  const std::int64_t value = integer(dotted_key);
  if (value < min || value > max) {
    std::string message = "value " + std::to_string(value);
    fail(dotted_key, message.append(" is outside the allowed range ").append(range));
  }
  return value;
}

std::int64_t TomlDocument::integer_or(std::string_view dotted_key, std::int64_t fallback, std::int64_t min,
                                      std::int64_t max) const {
  return has(dotted_key) ? integer(dotted_key, min, max) : fallback;
}

std::vector<double> TomlDocument::numbers_or_empty(std::string_view dotted_key) const {
  // Any finite double (the caller checks the physics).
  constexpr double kMax = std::numeric_limits<double>::max();
  return numbers_or_empty(dotted_key, Range{-kMax, kMax, ""});
}

std::vector<double> TomlDocument::numbers_or_empty(std::string_view dotted_key, const Range& range) const {
  std::vector<double> out;
  const auto node = impl_->table.at_path(dotted_key);
  if (!node) return out;
  used_.emplace(dotted_key);
  const toml::array* array = node.as_array();
  if (array == nullptr) fail(dotted_key, "expected an array of numbers");
  for (const toml::node& element : *array) {
    const std::string at =
        location(source_, element.source()) + ": " + std::string(dotted_key) + "[" + std::to_string(out.size()) + "]: ";
    const std::optional<double> value = element.value<double>();
    if (!value || !element.is_number()) throw ConfigError(at + "expected a number");
    if (!within(*value, range)) throw ConfigError(at + range_problem(*value, range));
    out.push_back(*value);
  }
  return out;
}

bool TomlDocument::boolean_or(std::string_view dotted_key, bool fallback) const {
  const auto node = impl_->table.at_path(dotted_key);
  if (!node) return fallback;
  used_.emplace(dotted_key);
  if (!node.is_boolean()) fail(dotted_key, "expected true or false");
  return *node.value<bool>();
}

std::string TomlDocument::string(std::string_view dotted_key) const {
  const auto node = impl_->table.at_path(dotted_key);
  if (!node) {
    throw ConfigError(source_ + ": missing required key '" + std::string(dotted_key) + "'");
  }
  used_.emplace(dotted_key);
  if (!node.is_string()) {
    fail(dotted_key, "expected a string");
  }
  return *node.value<std::string>();
}

std::string TomlDocument::string_or(std::string_view dotted_key, std::string fallback) const {
  return has(dotted_key) ? string(dotted_key) : std::move(fallback);
}

void TomlDocument::reject_unknown_keys_in(std::string_view table) const {
  const std::string prefix = std::string(table) + ".";
  std::vector<std::pair<std::string, toml::source_region>> leaves;
  collect_leaves(impl_->table, "", leaves);
  for (const auto& leaf : leaves) {
    if (leaf.first.starts_with(prefix) && used_.find(leaf.first) == used_.end()) {
      throw ConfigError(location(source_, leaf.second) + ": unknown key '" + leaf.first + "'");
    }
  }
}

void TomlDocument::leave_table(std::string_view table) const { left_tables_.emplace_back(std::string(table) + "."); }

void TomlDocument::reject_unknown_keys() const {
  std::vector<std::pair<std::string, toml::source_region>> leaves;
  collect_leaves(impl_->table, "", leaves);
  for (const auto& leaf : leaves) {
    // Not a structured binding: clang 14 (the fuzz build) cannot capture one.
    const std::string& name = leaf.first;
    const bool left = std::any_of(left_tables_.begin(), left_tables_.end(),
                                  [&name](const std::string& prefix) { return name.starts_with(prefix); });
    if (!left && used_.find(name) == used_.end()) {
      throw ConfigError(location(source_, leaf.second) + ": unknown key '" + name + "'");
    }
  }
}

}  // namespace glider::config
