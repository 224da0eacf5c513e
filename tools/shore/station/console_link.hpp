// SPDX-License-Identifier: Apache-2.0
#pragma once
// The glider's console as the shore sees it over a RUDICS call: a byte stream
// on a connected socket. Reads whole lines (journaled, handed to the dialog
// parser), notices the GliderDOS prompt (which has no line end) and the start
// of a Zmodem transfer, and writes commands. Every wait has a deadline; a
// line longer than the limit is cut (journaled as such) instead of growing
// without bound.
#include <cstddef>
#include <functional>
#include <string>

#include "session_journal.hpp"

namespace glider::shore {

class ConsoleLink {
 public:
  enum class Event { kPrompt, kZmodem, kTimeout, kClosed };
  using LineHandler = std::function<void(const std::string&)>;

  // `fd`: a connected socket, owned (closed) by the link.
  ConsoleLink(int fd, SessionJournal& journal, std::size_t max_line);
  ~ConsoleLink();
  ConsoleLink(const ConsoleLink&) = delete;
  ConsoleLink& operator=(const ConsoleLink&) = delete;

  // Reads until a prompt ends the text received (kPrompt, its text in
  // last_prompt()), the glider starts Zmodem (kZmodem, only if
  // `zmodem_ends_wait`; its first bytes are then in pending()), the link
  // closes (kClosed) or `timeout_s` passes (kTimeout).
  Event wait(double timeout_s, bool zmodem_ends_wait, const LineHandler& on_line);
  // Sends `text` and a carriage return, as typed at the console.
  bool send_line(const std::string& text);
  // Sends raw bytes (a control character such as Ctrl-R), journaled as ^X.
  bool send_control(char control);

  [[nodiscard]] int fd() const { return fd_; }
  [[nodiscard]] const std::string& last_prompt() const { return last_prompt_; }
  // Bytes read but not consumed as lines (the start of a Zmodem stream).
  std::string take_pending();
  // Bytes read from the socket by someone else (a Zmodem child's pump) that
  // belong to the console again.
  void put_back(const std::string& bytes);
  [[nodiscard]] bool closed() const { return closed_; }
  [[nodiscard]] std::size_t lines_cut() const { return lines_cut_; }

 private:
  bool write_all(const std::string& bytes, double timeout_s);
  // Splits complete lines off pending_; returns true when a prompt ends the rest.
  bool consume_lines(const LineHandler& on_line);

  int fd_;
  SessionJournal& journal_;
  std::size_t max_line_;
  std::string pending_;
  std::string last_prompt_;
  bool skipping_ = false;    // in the rest of a cut line
  std::size_t dropped_ = 0;  // bytes of it dropped so far
  bool dropped_cr_ = false;  // the last one dropped was a CR (part of the line end)
  std::size_t lines_cut_ = 0;
  bool closed_ = false;
};

}  // namespace glider::shore
