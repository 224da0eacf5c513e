// SPDX-License-Identifier: Apache-2.0
// A Keller transmitter for end-to-end runs (tests/linux/firmware_run.py):
// serves P1 = PRESSURE_BAR and TOB1 = 12 degC on DEVICE until SIGTERM.
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>

#include "keller_transmitter.hpp"

namespace {
volatile std::sig_atomic_t g_stop = 0;
void request_stop(int) { g_stop = 1; }
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s DEVICE PRESSURE_BAR\n", argv[0]);
    return 2;
  }
  std::signal(SIGTERM, request_stop);
  std::signal(SIGINT, request_stop);
  glider::test::KellerTransmitter transmitter(argv[1]);
  transmitter.set(std::strtof(argv[2], nullptr), 12.0f);
  std::printf("keller-transmitter: serving %s\n", argv[1]);
  std::fflush(stdout);
  while (!g_stop) pause();
  return 0;
}
