// SPDX-License-Identifier: Apache-2.0
#pragma once
// A helper process for the tests that talk to real peers (the actuator
// simulator, socat): started with fork/exec, killed with the test (and with
// the test runner, PR_SET_PDEATHSIG), its stdout readable line by line.
#include <string>
#include <vector>

namespace glider::test {

class ChildProcess {
 public:
  explicit ChildProcess(const std::vector<std::string>& argv);
  ~ChildProcess() { stop(); }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // The next line of its stdout ("" after timeout_ms or at its end).
  std::string read_line(int timeout_ms);
  // SIGTERM, then SIGKILL if it has not gone within a second; reaps it.
  void stop();

 private:
  int pid_ = -1;
  int stdout_fd_ = -1;
  std::string buffered_;
};

// A socat pty pair (two linked pseudo-terminals at unique paths), the
// RS-485 bus of the RTU tests.
class PtyPair {
 public:
  PtyPair();
  const std::string& device_end() const { return device_; }
  const std::string& glider_end() const { return glider_; }

 private:
  std::string device_;
  std::string glider_;
  ChildProcess socat_;
};

// The actuator simulator on the default board; `endpoint` is "--tcp
// 127.0.0.1:0" (any free port) or "--rtu DEVICE".
class Simulator {
 public:
  Simulator(const std::vector<std::string>& endpoint_and_faults);
  int tcp_port() const { return port_; }
  void stop() { process_.stop(); }

 private:
  ChildProcess process_;
  int port_ = -1;
};

}  // namespace glider::test
