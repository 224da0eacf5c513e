// SPDX-License-Identifier: Apache-2.0
#include "child_process.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace glider::test {

ChildProcess::ChildProcess(const std::vector<std::string>& argv) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) throw std::runtime_error("pipe failed");
  const pid_t parent = getpid();
  pid_ = fork();
  if (pid_ == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);
    dup2(pipe_fds[1], STDOUT_FILENO);
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
  close(pipe_fds[1]);
  stdout_fd_ = pipe_fds[0];
}

std::string ChildProcess::read_line(int timeout_ms) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (buffered_.find('\n') == std::string::npos) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    pollfd p{stdout_fd_, POLLIN, 0};
    if (left.count() <= 0 || poll(&p, 1, static_cast<int>(left.count())) <= 0) return "";
    char chunk[256];
    const ssize_t n = read(stdout_fd_, chunk, sizeof chunk);
    if (n <= 0) return "";
    buffered_.append(chunk, static_cast<std::size_t>(n));
  }
  const auto end = buffered_.find('\n');
  std::string line = buffered_.substr(0, end);
  buffered_.erase(0, end + 1);
  return line;
}

void ChildProcess::stop() {
  if (pid_ > 0) {
    kill(pid_, SIGTERM);
    int status = 0;
    for (int i = 0; i < 100 && waitpid(pid_, &status, WNOHANG) == 0; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      if (i == 99) {
        kill(pid_, SIGKILL);
        waitpid(pid_, &status, 0);
      }
    }
    pid_ = -1;
  }
  if (stdout_fd_ != -1) close(stdout_fd_);
  stdout_fd_ = -1;
}

namespace {

std::string unique_path(const char* tag) {
  static std::atomic<int> counter{0};
  return "/tmp/glider-modbus-test-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + "-" + tag;
}

bool exists(const std::string& path) {
  struct stat info {};
  return lstat(path.c_str(), &info) == 0;
}

}  // namespace

PtyPair::PtyPair()
    : device_(unique_path("device")),
      glider_(unique_path("glider")),
      socat_({"socat", "pty,raw,echo=0,link=" + device_, "pty,raw,echo=0,link=" + glider_}) {
  for (int i = 0; i < 500 && !(exists(device_) && exists(glider_)); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!exists(device_) || !exists(glider_)) throw std::runtime_error("socat did not create the pty pair");
}

Simulator::Simulator(const std::vector<std::string>& endpoint_and_faults)
    : process_([&] {
        std::vector<std::string> argv{GLIDER_ACTUATOR_SIM, "--time-scale", "20"};
        argv.insert(argv.end(), endpoint_and_faults.begin(), endpoint_and_faults.end());
        return argv;
      }()) {
  const std::string line = process_.read_line(5000);
  const auto serving = line.find("serving ");
  if (serving == std::string::npos) throw std::runtime_error("simulator did not start: '" + line + "'");
  const auto tcp = line.find("serving tcp ");
  if (tcp != std::string::npos) {
    const auto colon = line.find(':', tcp + 12);
    port_ = std::stoi(line.substr(colon + 1));
  }
}

}  // namespace glider::test
