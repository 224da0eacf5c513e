// SPDX-License-Identifier: Apache-2.0
// The target's flight-log writer as a process that never stops on its own:
// hands rows to RingBufferLog as fast as it takes them, so that
// kill9_logs.py can kill it with SIGKILL at any moment and check that the
// file holds whole rows only.
//   ring_log_writer FILE
#include <cstdio>
#include <thread>

#include "glider/target/ring_log.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: ring_log_writer FILE\n");
    return 2;
  }
  glider::target::RingLogOptions options;
  options.metadata = {{"source", "ring_log_writer (kill -9 test)"}};
  glider::target::RingBufferLog log(argv[1], options);
  std::printf("writing\n");
  std::fflush(stdout);
  glider::hal::FlightLogRecord r;
  for (long long i = 0;; ++i) {
    r.time_us = i * 1000;
    r.m_depth = 0.001 * static_cast<double>(i);
    r.x_yo_count = static_cast<int>(i % 100000);
    while (!log.write(r)) std::this_thread::yield();
  }
}
