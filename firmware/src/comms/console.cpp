// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/comms/console.hpp"

#include <fnmatch.h>

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace glider::fw::comms {
namespace {

constexpr char kCtrlC = 0x03, kCtrlF = 0x06, kCtrlR = 0x12, kCtrlW = 0x17;
constexpr char kBackspace = 0x08, kDelete = 0x7f;
// callback <minutes>: at least a minute, at most a day at the surface waiting.
constexpr config::Range kCallbackMinutes{1.0, 1440.0, "min"};

// A whole-string decimal number (strtod), NaN when the text is not one.
double parse_number(const char* text) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0') return std::nan("");
  return value;
}

}  // namespace

void Console::newline_if_needed() {
  if (!column_zero_) out_.append("\r\n");
  column_zero_ = true;
}

void Console::refuse(const char* format, const char* detail) {
  ++stats_.refused;
  out_.appendf(format, detail);
  out_.append("\r\n");
}

bool Console::feed(std::span<const std::uint8_t> bytes) {
  bool keystroke = false;
  for (const std::uint8_t byte : bytes) {
    const char c = static_cast<char>(byte);
    const bool after_cr = last_was_cr_;
    last_was_cr_ = c == '\r';
    if (c == '\n' && after_cr) continue;  // CR LF is one end of line
    keystroke = true;
    if (c == '\r' || c == '\n') {
      out_.append("\r\n");
      column_zero_ = true;
      on_line();
      continue;
    }
    if (c == kCtrlC || c == kCtrlF || c == kCtrlR || c == kCtrlW) {
      on_control(c);
      continue;
    }
    if (c == kBackspace || c == kDelete) {
      if (length_ > 0 && !overlong_) {
        --length_;
        out_.append("\b \b");
      }
      continue;
    }
    const char printable = c == '\t' ? ' ' : c;
    if (byte >= 0x80 || printable < 0x20) {
      ++stats_.ignored_bytes;
      continue;
    }
    ++typed_;
    if (length_ >= kMaxLine) {
      overlong_ = true;
      continue;
    }
    line_[length_++] = printable;
    out_.append(std::string_view(&printable, 1));
    column_zero_ = false;
  }
  return keystroke;
}

void Console::on_control(char key) {
  // The real console shows the key as ^X at the head of the next line.
  newline_if_needed();
  out_.appendf("^%c\r\n", static_cast<char>(key + '@'));
  switch (key) {
    case kCtrlC:
      actions_.end_mission();
      break;
    case kCtrlR:
      actions_.resume_mission();
      break;
    case kCtrlF:
      actions_.reread_mafiles();
      break;
    case kCtrlW:
      actions_.device_report();
      break;
    default:
      break;
  }
  actions_.print_prompt();
}

void Console::on_line() {
  answer_line();
  // The prompt says the console is ready again; a transfer prints it when it ends.
  if (!transfer_running_) actions_.print_prompt();
  transfer_running_ = false;
}

void Console::answer_line() {
  const std::size_t typed = typed_;
  const bool overlong = overlong_;
  line_[length_] = '\0';
  const std::size_t length = length_;
  length_ = 0;
  typed_ = 0;
  overlong_ = false;
  if (overlong) {
    ++stats_.overlong;
    ++stats_.refused;
    out_.appendf("ERROR: line too long (%zu characters, at most %zu): ignored\r\n", typed, kMaxLine);
    return;
  }
  if (length == 0) return;
  ++stats_.lines;
  // Tokens in place: spaces become the ends of strings.
  std::array<const char*, kMaxTokens> tokens{};
  std::size_t count = 0;
  char* p = line_.data();
  while (*p != '\0') {
    while (*p == ' ') *p++ = '\0';
    if (*p == '\0') break;
    if (count == kMaxTokens) {
      refuse("ERROR: too many arguments (at most %s)", "7");
      return;
    }
    tokens[count++] = p;
    while (*p != '\0' && *p != ' ') ++p;
  }
  if (count == 0) return;
  bool bang = false;
  if (tokens[0][0] == '!') {
    bang = true;
    ++tokens[0];
    if (tokens[0][0] == '\0') {
      refuse("ERROR: %s needs a command after it", "!");
      return;
    }
  }
  execute(std::span<const char* const>(tokens.data(), count), bang);
}

void Console::execute(std::span<const char* const> t, bool bang) {
  const char* command = t[0];
  const bool running = actions_.mission_running();
  auto needs_bang = [&]() {
    if (running && !bang) {
      ++stats_.refused;
      out_.appendf("ERROR: a mission is running: type !%s to %s a parameter during it\r\n", command, command);
      return true;
    }
    return false;
  };
  if (std::strcmp(command, "whoru") == 0) {
    print_vehicle_name(actions_.vehicle_name(), out_);
  } else if (std::strcmp(command, "put") == 0) {
    if (!needs_bang()) command_put(t);
  } else if (std::strcmp(command, "get") == 0) {
    if (!needs_bang()) command_get(t);
  } else if (std::strcmp(command, "send") == 0 || std::strcmp(command, "s") == 0) {
    command_send(t, true);
  } else if (std::strcmp(command, "zs") == 0) {
    command_send(t, false);
  } else if (std::strcmp(command, "zr") == 0) {
    if (transfer_ == nullptr || !transfer_->begin_receive()) {
      refuse("ERROR: %s: the file transfer is busy or not fitted", "zr");
    } else {
      transfer_running_ = true;
      actions_.transfer_started();
    }
  } else if (std::strcmp(command, "callback") == 0) {
    const double minutes = t.size() == 2 ? parse_number(t[1]) : std::nan("");
    if (!config::within(minutes, kCallbackMinutes)) {
      ++stats_.refused;
      out_.appendf("ERROR: callback minutes value %s is outside the allowed range [%g, %g] %s\r\n",
                   t.size() == 2 ? t[1] : "(missing)", kCallbackMinutes.min, kCallbackMinutes.max,
                   kCallbackMinutes.unit);
    } else {
      actions_.callback(minutes);
    }
  } else if (std::strcmp(command, "sequence") == 0 || std::strcmp(command, "run") == 0) {
    if (running) {
      refuse("ERROR: %s: a mission is already running (Control-C ends it first)", command);
    } else if (!actions_.run_mission()) {
      refuse("ERROR: %s: the mission is complete; nothing left to run", command);
    }
  } else if (std::strcmp(command, "exit") == 0) {
    if (t.size() == 2 && std::strcmp(t[1], "reset") == 0) {
      actions_.exit_reset();
    } else {
      refuse("ERROR: %s: only `exit reset` is supported", command);
    }
  } else {
    char shown[24];
    std::snprintf(shown, sizeof shown, "%.20s", command);
    ++stats_.refused;
    out_.appendf("ERROR: unknown command: %s (known: whoru put get send s zs zr callback sequence run exit)\r\n",
                 shown);
  }
}

void Console::command_put(std::span<const char* const> t) {
  if (t.size() != 3) {
    refuse("ERROR: usage: %s NAME VALUE", "put");
    return;
  }
  const Parameter* p = parameters_.find(t[1]);
  if (p == nullptr) {
    refuse("ERROR: put refused: %s is not a u_ parameter of this vehicle", t[1]);
    return;
  }
  const double value = parse_number(t[2]);
  if (!config::within(value, p->range)) {
    ++stats_.refused;
    char shown[24];
    std::snprintf(shown, sizeof shown, "%.20s", t[2]);
    out_.appendf("ERROR: put refused: %s value %s is outside the allowed range [%g, %g] %s\r\n", p->name, shown,
                 p->range.min, p->range.max, p->range.unit);
    return;
  }
  *p->value = value;
  out_.appendf("%s(%s)=%.15g\r\n", p->name, p->range.unit, value);
}

void Console::command_get(std::span<const char* const> t) {
  if (t.size() != 2) {
    refuse("ERROR: usage: %s NAME", "get");
    return;
  }
  const Parameter* p = parameters_.find(t[1]);
  if (p == nullptr) {
    refuse("ERROR: get: %s is not a u_ parameter of this vehicle", t[1]);
    return;
  }
  out_.appendf("%s(%s)=%.15g\r\n", p->name, p->range.unit, *p->value);
}

void Console::command_send(std::span<const char* const> t, bool allow_num) {
  if (transfer_ == nullptr) {
    refuse("ERROR: %s: no file transfer engine is fitted", t[0]);
    return;
  }
  long limit = -1;
  std::size_t patterns = 0;
  std::array<const char*, kMaxTokens> globs{};
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (allow_num && std::strncmp(t[i], "-num=", 5) == 0) {
      const double n = parse_number(t[i] + 5);
      if (!(n >= 1.0 && n <= static_cast<double>(kMaxFilesPerSend) && n == std::floor(n))) {
        ++stats_.refused;
        out_.appendf("ERROR: %s: -num value %.20s is outside the allowed range [1, %zu] files\r\n", t[0], t[i] + 5,
                     kMaxFilesPerSend);
        return;
      }
      limit = static_cast<long>(n);
    } else if (t[i][0] == '-') {
      refuse("ERROR: unknown option %s", t[i]);
      return;
    } else {
      globs[patterns++] = t[i];
    }
  }
  if (patterns == 0) {
    refuse("ERROR: usage: %s [-num=N] GLOB...", t[0]);
    return;
  }
  // Newest first (the engine lists oldest first), then back to oldest first.
  transfer_->list_files();
  std::size_t picked = 0;
  const std::size_t max = limit > 0 ? static_cast<std::size_t>(limit) : kMaxFilesPerSend;
  for (std::size_t k = transfer_->file_count(); k > 0 && picked < max; --k) {
    const char* name = transfer_->file_name(k - 1);
    for (std::size_t g = 0; g < patterns; ++g) {
      if (fnmatch(globs[g], name, 0) == 0) {
        std::snprintf(picked_[picked].text, kMaxFileName, "%s", name);
        ++picked;
        break;
      }
    }
  }
  if (picked == 0) {
    refuse("ERROR: %s: no file matches", t[0]);
    return;
  }
  for (std::size_t i = 0; i < picked / 2; ++i) std::swap(picked_[i], picked_[picked - 1 - i]);
  if (!transfer_->begin_send(std::span<const FileName>(picked_.data(), picked))) {
    refuse("ERROR: %s: the file transfer is busy", t[0]);
    return;
  }
  out_.appendf("Sending %zu file(s)\r\n", picked);
  transfer_running_ = true;
  actions_.transfer_started();
}

}  // namespace glider::fw::comms
