// SPDX-License-Identifier: Apache-2.0
#include "console_link.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>

#include "surface_dialog.hpp"

namespace glider::shore {
namespace {

using Clock = std::chrono::steady_clock;

int remaining_ms(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return static_cast<int>(std::clamp<long long>(left, 0, 1000));
}

Clock::time_point deadline_after(double seconds) {
  return Clock::now() + std::chrono::milliseconds(static_cast<long long>(seconds * 1000.0));
}

// A Zmodem header starts ZPAD ZDLE (ZDLE = Ctrl-X) and 'B' (hex: how sz's
// ZRQINIT and rz's ZRINIT are normally sent), 'A' or 'C' (binary, CRC-16/32).
std::size_t zmodem_start(const std::string& text) {
  for (std::size_t at = text.find("*\x18"); at != std::string::npos; at = text.find("*\x18", at + 1)) {
    if (at + 2 < text.size() && (text[at + 2] == 'A' || text[at + 2] == 'B' || text[at + 2] == 'C')) return at;
  }
  return std::string::npos;
}

}  // namespace

ConsoleLink::ConsoleLink(int fd, SessionJournal& journal, std::size_t max_line)
    : fd_(fd), journal_(journal), max_line_(max_line) {
  // Non-blocking: every read and write below waits in poll(2) with a deadline.
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) | O_NONBLOCK);
}

ConsoleLink::~ConsoleLink() { ::close(fd_); }

void ConsoleLink::put_back(const std::string& bytes) { pending_.insert(0, bytes); }

std::string ConsoleLink::take_pending() {
  std::string out;
  out.swap(pending_);
  return out;
}

bool ConsoleLink::consume_lines(const LineHandler& on_line) {
  for (;;) {
    const std::size_t end = pending_.find('\n');
    if (skipping_) {
      // The rest of a cut line: dropped up to its end, counted for the journal.
      const std::size_t drop = end == std::string::npos ? pending_.size() : end;
      dropped_ += drop;
      if (drop > 0) dropped_cr_ = pending_[drop - 1] == '\r';
      pending_.erase(0, end == std::string::npos ? drop : end + 1);
      if (end == std::string::npos) return false;
      journal_.write('*', "line cut: " + std::to_string(dropped_ - (dropped_cr_ ? 1 : 0)) + " more bytes dropped");
      skipping_ = false;
      continue;
    }
    if (end == std::string::npos) break;
    std::string line = pending_.substr(0, end);
    pending_.erase(0, end + 1);
    while (!line.empty() && line.back() == '\r') line.pop_back();
    journal_.write('<', line);
    on_line(line);
  }
  if (pending_.size() > max_line_) {
    std::string head = pending_.substr(0, max_line_);
    journal_.write('<', head);
    on_line(head);
    ++lines_cut_;
    skipping_ = true;
    dropped_ = pending_.size() - max_line_;
    dropped_cr_ = pending_.back() == '\r';
    pending_.clear();
    return false;
  }
  std::string tail = pending_;
  while (!tail.empty() && (tail.back() == ' ' || tail.back() == '\r')) tail.pop_back();
  const std::string prompt = match_prompt(tail);
  // The prompt is the last thing the glider prints before it waits for us.
  if (!prompt.empty() && tail.size() >= prompt.size() &&
      tail.compare(tail.size() - prompt.size(), prompt.size(), prompt) == 0) {
    journal_.write('<', pending_);
    on_line(pending_);
    last_prompt_ = prompt;
    pending_.clear();
    return true;
  }
  return false;
}

ConsoleLink::Event ConsoleLink::wait(double timeout_s, bool zmodem_ends_wait, const LineHandler& on_line) {
  const Clock::time_point deadline = deadline_after(timeout_s);
  if (consume_lines(on_line)) return Event::kPrompt;
  char buffer[4096];
  while (!closed_) {
    if (Clock::now() >= deadline) return Event::kTimeout;
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, remaining_ms(deadline));
    if (ready < 0 && errno != EINTR) {
      closed_ = true;
      break;
    }
    if (ready <= 0) continue;
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) {
      closed_ = true;
      break;
    }
    if (n < 0) continue;
    pending_.append(buffer, static_cast<std::size_t>(n));
    if (zmodem_ends_wait) {
      const std::size_t start = zmodem_start(pending_);
      if (start != std::string::npos) {
        // Text before the header is console output (the echo of the command).
        std::string zmodem = pending_.substr(start > 0 && pending_[start - 1] == '*' ? start - 1 : start);
        pending_.erase(pending_.size() - zmodem.size());
        consume_lines(on_line);
        if (!pending_.empty()) journal_.write('<', pending_);
        pending_ = zmodem;
        return Event::kZmodem;
      }
    }
    if (consume_lines(on_line)) return Event::kPrompt;
  }
  if (!pending_.empty() && !skipping_) {
    journal_.write('<', pending_);
    on_line(pending_);
    pending_.clear();
  }
  return Event::kClosed;
}

bool ConsoleLink::write_all(const std::string& bytes, double timeout_s) {
  const Clock::time_point deadline = deadline_after(timeout_s);
  std::size_t done = 0;
  while (done < bytes.size()) {
    if (closed_ || Clock::now() >= deadline) return false;
    const ssize_t n = ::send(fd_, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
      pollfd p{fd_, POLLOUT, 0};
      ::poll(&p, 1, remaining_ms(deadline));
      continue;
    }
    closed_ = true;
    return false;
  }
  return true;
}

bool ConsoleLink::send_line(const std::string& text) {
  journal_.write('>', text);
  return write_all(text + "\r", 30.0);
}

bool ConsoleLink::send_control(char control) {
  journal_.write('>', std::string("^") + static_cast<char>(control + '@'));
  return write_all(std::string(1, control), 30.0);
}

}  // namespace glider::shore
