// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Keller Series 30 class depth transmitter on its serial line: Modbus
// RTU (libmodbus on the pty's master side), P1 and TOB1 as Keller floats
// (hal/linux/include/glider/hal_linux/keller_depth.hpp), the pressure taken
// from the model at the moment the request arrives.
#include <modbus/modbus.h>

#include <functional>
#include <string>

namespace glider::plant {

struct KellerReading {
  double pressure_bar = 0.0;
  double temperature_c = 0.0;
};

class KellerServer {
 public:
  // `fd`: the line (pty master), owned by the caller. Throws on failure.
  KellerServer(int fd, const std::string& device_name, int slave);
  ~KellerServer();
  KellerServer(const KellerServer&) = delete;
  KellerServer& operator=(const KellerServer&) = delete;

  // The line is readable: takes one request and, unless `silent`, answers
  // it with `measure()` taken now. Bounded by the byte timeout.
  void on_readable(const std::function<KellerReading()>& measure, bool silent);

  unsigned long long requests() const { return requests_; }
  unsigned long long rejected() const { return rejected_; }  // bad CRC, other slave, garbled

 private:
  void put_float(int address, double value);

  modbus_t* context_ = nullptr;
  modbus_mapping_t* mapping_ = nullptr;
  unsigned long long requests_ = 0;
  unsigned long long rejected_ = 0;
};

}  // namespace glider::plant
