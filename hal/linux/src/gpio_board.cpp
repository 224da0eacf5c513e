// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/gpio_board.hpp"

#include <array>

#include "glider/config/toml_document.hpp"

namespace glider::hal_linux {
namespace {

using config::TomlDocument;

struct RoleInfo {
  LineRole role;
  const char* key;
  LineDirection direction;
  bool required;
};

// Direction is the role's, not a setting: a leak detector driven as an
// output would be a wiring accident waiting to happen.
constexpr std::array<RoleInfo, kLineRoleCount> kRoles{{
    {LineRole::kLeak, "leak", LineDirection::kInput, true},
    {LineRole::kDropWeight, "drop_weight", LineDirection::kOutput, true},
    {LineRole::kPumpEnable, "pump_enable", LineDirection::kOutput, false},
    {LineRole::kValve, "valve", LineDirection::kOutput, false},
    {LineRole::kPumpLimitIn, "pump_limit_in", LineDirection::kInput, false},
    {LineRole::kPumpLimitOut, "pump_limit_out", LineDirection::kInput, false},
    {LineRole::kSlideLimitFwd, "slide_limit_fwd", LineDirection::kInput, false},
    {LineRole::kSlideLimitAft, "slide_limit_aft", LineDirection::kInput, false},
}};

LineBias read_bias(const TomlDocument& doc, const std::string& key) {
  const std::string bias = doc.string_or(key, "as-is");
  if (bias == "as-is") return LineBias::kAsIs;
  if (bias == "disable") return LineBias::kDisabled;
  if (bias == "pull-up") return LineBias::kPullUp;
  if (bias == "pull-down") return LineBias::kPullDown;
  doc.fail(key, "expected \"as-is\", \"disable\", \"pull-up\" or \"pull-down\", not \"" + bias + "\"");
}

std::string non_empty_string(const TomlDocument& doc, const std::string& key) {
  std::string value = doc.string(key);
  if (value.empty()) doc.fail(key, "must not be empty");
  return value;
}

LineConfig read_line(const TomlDocument& doc, const RoleInfo& info) {
  const std::string table = std::string("lines.") + info.key;
  const auto key = [&](const char* leaf) { return table + "." + leaf; };
  LineConfig line;
  line.role = info.role;
  line.direction = info.direction;
  line.where = doc.where(table);
  line.chip = non_empty_string(doc, key("chip"));
  line.line = non_empty_string(doc, key("line"));
  line.active_low = doc.boolean_or(key("active_low"), false);
  line.bias = read_bias(doc, key("bias"));
  if (info.direction == LineDirection::kInput) {
    line.latch = doc.boolean_or(key("latch"), false);
  } else {
    line.initial_active = doc.boolean_or(key("initial_active"), false);
    if (line.initial_active && info.role == LineRole::kDropWeight) {
      doc.fail(key("initial_active"), "the drop weight must never fire at start-up");
    }
  }
  return line;
}

GpioBoard read_board(const TomlDocument& doc) {
  GpioBoard board;
  board.source = doc.source();
  doc.string_or("name", "");
  doc.string_or("description", "");
  board.consumer = doc.string_or("consumer", board.consumer);
  if (board.consumer.empty() || board.consumer.size() > 31) doc.fail("consumer", "must be 1 to 31 characters");
  for (const RoleInfo& info : kRoles) {
    const std::string table = std::string("lines.") + info.key;
    if (doc.has(table)) {
      board.lines.push_back(read_line(doc, info));
    } else if (info.required) {
      doc.fail("lines", std::string("missing the required line [") + table + "]");
    }
  }
  doc.reject_unknown_keys();  // a misspelt role or key is an error, not a line silently absent
  for (std::size_t i = 0; i < board.lines.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (board.lines[i].chip == board.lines[j].chip && board.lines[i].line == board.lines[j].line) {
        doc.fail(
            std::string("lines.") + role_key(board.lines[i].role) + ".line",
            "line \"" + board.lines[i].line + "\" is already used by [lines." + role_key(board.lines[j].role) + "]");
      }
    }
  }
  return board;
}

}  // namespace

const char* role_key(LineRole role) {
  for (const RoleInfo& info : kRoles) {
    if (info.role == role) return info.key;
  }
  return "?";
}

const LineConfig* GpioBoard::find(LineRole role) const {
  for (const LineConfig& line : lines) {
    if (line.role == role) return &line;
  }
  return nullptr;
}

GpioBoard load_gpio_board(const std::filesystem::path& path) { return read_board(TomlDocument::load(path)); }

GpioBoard parse_gpio_board(const std::string& text, const std::string& source_name) {
  return read_board(TomlDocument::parse(text, source_name));
}

}  // namespace glider::hal_linux
