// SPDX-License-Identifier: Apache-2.0
#pragma once
// The GliderDOS console subset a pilot types over the call: a bounded line
// editor with the real console's echo (control characters shown as ^C at
// the head of the next line) and the commands of docs/comms.md, Commands.
// Garbage, overlong lines and unknown commands are refused in words; nothing
// here allocates or can stop the loop.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "glider/firmware/comms/file_transfer.hpp"
#include "glider/firmware/comms/parameters.hpp"
#include "glider/firmware/comms/surface_dialog.hpp"

namespace glider::fw::comms {

// What the console's keys and commands do to the vehicle (the comms task).
class ConsoleActions {
 public:
  virtual ~ConsoleActions() = default;
  virtual const char* vehicle_name() const = 0;
  virtual bool mission_running() const = 0;
  virtual void end_mission() = 0;     // ^C
  virtual void resume_mission() = 0;  // ^R
  virtual void reread_mafiles() = 0;  // ^F
  virtual void device_report() = 0;   // ^W
  virtual void callback(double minutes) = 0;
  virtual bool run_mission() = 0;  // sequence / run (after ^C)
  virtual void exit_reset() = 0;
  virtual void transfer_started() = 0;  // send/s/zs/zr handed to the engine
  // The GliderDOS prompt, after each answered line or key (none while a transfer runs).
  virtual void print_prompt() {}
};

struct ConsoleStats {
  std::uint32_t lines = 0;
  std::uint32_t refused = 0;  // unknown commands, bad arguments, refused puts
  std::uint32_t overlong = 0;
  std::uint32_t ignored_bytes = 0;  // non-printable bytes that are no command key
};

class Console {
 public:
  static constexpr std::size_t kMaxLine = 128;  // characters of a command line (more is refused)
  static constexpr std::size_t kMaxTokens = 8;

  Console(ConsoleActions& actions, ParameterTable& parameters, FileTransfer* transfer, DialogQueue& out)
      : actions_(actions), parameters_(parameters), transfer_(transfer), out_(out) {}

  // Feeds typed bytes; returns true if any was a keystroke (resets the wait).
  bool feed(std::span<const std::uint8_t> bytes);
  const ConsoleStats& stats() const { return stats_; }

 private:
  void on_control(char key);
  void on_line();
  void answer_line();
  void execute(std::span<const char* const> tokens, bool bang);
  void command_put(std::span<const char* const> tokens);
  void command_get(std::span<const char* const> tokens);
  void command_send(std::span<const char* const> tokens, bool allow_num);
  void refuse(const char* format, const char* detail);
  void newline_if_needed();

  ConsoleActions& actions_;
  ParameterTable& parameters_;
  FileTransfer* transfer_;
  DialogQueue& out_;
  std::array<char, kMaxLine + 1> line_{};
  std::size_t length_ = 0;
  std::size_t typed_ = 0;  // characters typed on this line, kept or not
  bool overlong_ = false;
  bool transfer_running_ = false;  // the line just answered started a transfer
  bool column_zero_ = true;
  bool last_was_cr_ = false;
  std::array<FileName, kMaxFilesPerSend> picked_{};
  ConsoleStats stats_{};
};

}  // namespace glider::fw::comms
