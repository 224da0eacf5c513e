// SPDX-License-Identifier: Apache-2.0
#include "zmodem_child.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <stdexcept>

namespace glider::shore {
namespace {

using Clock = std::chrono::steady_clock;

void set_nonblocking(int fd) { ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK); }

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

// Writes what it can of `buffer` to `fd` without blocking; false on a broken pipe or socket.
bool flush_some(int fd, std::string& buffer) {
  if (buffer.empty()) return true;
  const ssize_t n = ::send(fd, buffer.data(), buffer.size(), MSG_NOSIGNAL);
  if (n < 0 && errno == ENOTSOCK) {
    const ssize_t w = ::write(fd, buffer.data(), buffer.size());
    if (w > 0) buffer.erase(0, static_cast<std::size_t>(w));
    return w >= 0 || errno == EAGAIN || errno == EINTR;
  }
  if (n > 0) buffer.erase(0, static_cast<std::size_t>(n));
  return n >= 0 || errno == EAGAIN || errno == EINTR;
}

// Reads what is there; returns false at end of file or on an error.
bool read_some(int fd, std::string& into, std::uint64_t* count) {
  char buffer[8192];
  const ssize_t n = ::read(fd, buffer, sizeof buffer);
  if (n > 0) {
    into.append(buffer, static_cast<std::size_t>(n));
    if (count != nullptr) *count += static_cast<std::uint64_t>(n);
    return true;
  }
  return n < 0 && (errno == EAGAIN || errno == EINTR);
}

// Splits what the glider sends into the Zmodem session and the console text
// that follows it. After the glider's ZFIN hex header ("**" ZDLE "B08") the
// child needs only the rest of that header and the "OO" that ends a session;
// the first other byte (the glider's prompt, typically) and all after it are
// console text again, held for the shore instead of being fed to an exiting
// child.
class SessionEndWatch {
 public:
  // Appends `bytes` to `to_child` or, once the session is over, to `held`.
  void route(const std::string& bytes, std::string& to_child, std::string& held) {
    for (const char c : bytes) {
      if (holding_) {
        held += c;
        continue;
      }
      if (fin_seen_ && !part_of_session_end(c)) {
        holding_ = true;
        held += c;
        continue;
      }
      to_child += c;
      window_ += c;
      if (window_.size() > kFinHeader.size()) window_.erase(0, 1);
      if (window_ == kFinHeader) fin_seen_ = true;
    }
  }

 private:
  static bool part_of_session_end(char c) {
    const auto b = static_cast<unsigned char>(c);
    return std::isxdigit(b) || c == '\r' || c == '\n' || b == 0x8a || b == 0x11 || c == 'O' || c == '*' || b == 0x18 ||
           c == 'B';
  }
  inline static const std::string kFinHeader = std::string("**\x18") + "B08";
  std::string window_;
  bool fin_seen_ = false;
  bool holding_ = false;
};

}  // namespace

ZmodemRun run_zmodem_child(const std::vector<std::string>& argv, const std::filesystem::path& cwd, int socket_fd,
                           const std::string& first_bytes, double idle_timeout_s, double total_timeout_s,
                           const std::atomic<bool>& stop) {
  int in_pipe[2], out_pipe[2], err_pipe[2];
  if (::pipe2(in_pipe, O_CLOEXEC) != 0 || ::pipe2(out_pipe, O_CLOEXEC) != 0 || ::pipe2(err_pipe, O_CLOEXEC) != 0) {
    throw std::runtime_error("zmodem: cannot create pipes");
  }
  std::vector<char*> args;
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  const std::string dir = cwd.string();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("zmodem: cannot start " + argv.front());
  if (pid == 0) {
    // Only async-signal-safe calls between fork and exec (the shore is multi-threaded).
    ::signal(SIGPIPE, SIG_DFL);  // lrzsz as from a shell (the shore ignores SIGPIPE)
    ::dup2(in_pipe[0], 0);
    ::dup2(out_pipe[1], 1);
    ::dup2(err_pipe[1], 2);
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    ::execvp(args[0], args.data());
    ::_exit(127);
  }
  int to_child = in_pipe[1], from_child = out_pipe[0], child_err = err_pipe[0];
  ::close(in_pipe[0]);
  ::close(out_pipe[1]);
  ::close(err_pipe[1]);
  set_nonblocking(to_child);
  set_nonblocking(from_child);
  set_nonblocking(child_err);

  ZmodemRun run;
  std::string for_child, for_glider;
  SessionEndWatch end_watch;
  end_watch.route(first_bytes, for_child, run.leftover);
  run.bytes_from_glider = first_bytes.size();
  const auto start = Clock::now();
  auto last_traffic = start;
  bool child_done = false;
  while (!child_done) {
    if (stop) {
      run.stopped = true;
      break;
    }
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - last_traffic).count() > idle_timeout_s ||
        std::chrono::duration<double>(now - start).count() > total_timeout_s) {
      run.timed_out = true;
      break;
    }
    pollfd fds[4] = {{socket_fd, static_cast<short>(run.carrier_lost ? 0 : POLLIN), 0},
                     {from_child, POLLIN, 0},
                     {child_err, static_cast<short>(child_err >= 0 ? POLLIN : 0), 0},
                     {to_child, static_cast<short>(for_child.empty() ? 0 : POLLOUT), 0}};
    if (!for_glider.empty() && !run.carrier_lost) fds[0].events |= POLLOUT;
    if (::poll(fds, 4, 200) < 0 && errno != EINTR) break;
    if (fds[0].revents & (POLLIN | POLLHUP | POLLERR)) {
      std::string bytes;
      if (!read_some(socket_fd, bytes, &run.bytes_from_glider)) run.carrier_lost = true;
      if (!bytes.empty()) last_traffic = Clock::now();
      end_watch.route(bytes, for_child, run.leftover);
    }
    if (run.carrier_lost) break;
    if (fds[2].revents & (POLLIN | POLLHUP)) {
      if (!read_some(child_err, run.diagnostics, nullptr)) close_fd(child_err);
    }
    if (fds[1].revents & (POLLIN | POLLHUP)) {
      const std::size_t before = for_glider.size();
      if (!read_some(from_child, for_glider, nullptr)) child_done = true;
      if (for_glider.size() != before) last_traffic = Clock::now();
    }
    if (to_child >= 0 && !flush_some(to_child, for_child)) close_fd(to_child);
    const std::size_t before = for_glider.size();
    if (!flush_some(socket_fd, for_glider)) run.carrier_lost = true;
    run.bytes_to_glider += before - for_glider.size();
  }
  // Done, dead link or limit: the child's last words (Zmodem "OO") go out, then it is ended.
  for (int i = 0; i < 50 && !for_glider.empty() && !run.carrier_lost; ++i) {
    const std::size_t before = for_glider.size();
    if (!flush_some(socket_fd, for_glider)) break;
    run.bytes_to_glider += before - for_glider.size();
    if (!for_glider.empty()) ::usleep(20000);
  }
  // What the child never took is the glider's console again (e.g. its prompt).
  if (child_done) run.leftover.insert(0, for_child);
  int status = 0;
  if (!child_done || run.carrier_lost || run.timed_out || run.stopped) {
    // SIGKILL before its pipes close: rz given EOF or SIGTERM deletes the
    // file it was receiving, and that partial file is what the next call
    // resumes (rz -r).
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
  }
  close_fd(to_child);
  close_fd(from_child);
  if (child_done && !run.carrier_lost && !run.timed_out && !run.stopped) {
    for (int i = 0; i < 100 && ::waitpid(pid, &status, WNOHANG) == 0; ++i) ::usleep(20000);
    if (::waitpid(pid, nullptr, WNOHANG) == 0) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
    }
  }
  for (int i = 0; i < 1000 && child_err >= 0 && read_some(child_err, run.diagnostics, nullptr); ++i) {
  }
  close_fd(child_err);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return run;
}

std::vector<std::string> completed_receptions(const std::string& diagnostics) {
  // rz opens a file at ZFILE and closes it at ZEOF, before the next ZFILE:
  // a "Receiving:" line means the file before it is complete, and so does
  // "Transfer complete" for the last one.
  std::vector<std::string> done;
  std::string current;
  std::size_t at = 0;
  while (at < diagnostics.size()) {
    std::size_t end = diagnostics.find_first_of("\r\n", at);
    if (end == std::string::npos) end = diagnostics.size();
    const std::string line = diagnostics.substr(at, end - at);
    at = end + 1;
    static const std::string receiving = "Receiving: ";
    if (const std::size_t name = line.find(receiving); name != std::string::npos) {
      if (!current.empty()) done.push_back(current);
      current = line.substr(name + receiving.size());
      while (!current.empty() && current.back() == ' ') current.pop_back();
    } else if (line.find("Transfer complete") != std::string::npos && !current.empty()) {
      done.push_back(current);
      current.clear();
    }
  }
  return done;
}

}  // namespace glider::shore
