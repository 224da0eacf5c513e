// SPDX-License-Identifier: Apache-2.0
#pragma once
// The GPS and the compass on serial lines: each read() takes the bytes that
// have arrived (bounded, non-blocking), decodes the complete sentences and
// returns the newest good value. A value older than the sensor's stale
// limit is returned invalid (and counted): a GPS under water or a compass
// whose cable came loose stops updating, it does not say so.
#include <algorithm>
#include <cstdint>
#include <memory>

#include "glider/hal/attitude_sensor.hpp"
#include "glider/hal/clock.hpp"
#include "glider/hal/gps.hpp"
#include "glider/hal_linux/nmea.hpp"
#include "glider/hal_linux/sentence_decoders.hpp"
#include "glider/hal_linux/serial_port.hpp"

namespace glider::hal_linux {

// A serial port cut into NMEA lines. At most kMaxBytesPerPoll bytes per
// call, so a babbling device cannot hold the loop.
class NmeaSerialStream {
 public:
  static constexpr std::size_t kMaxBytesPerPoll = 4096;
  explicit NmeaSerialStream(std::unique_ptr<SerialPort> port) : port_(std::move(port)) {}

  template <typename OnLine>
  void poll(OnLine&& on_line) noexcept {
    std::size_t taken = 0;
    while (taken < kMaxBytesPerPoll) {
      const long n = port_->read_some(chunk_, std::min(sizeof chunk_, kMaxBytesPerPoll - taken));
      if (n <= 0) return;
      taken += static_cast<std::size_t>(n);
      framer_.feed(std::string_view(chunk_, static_cast<std::size_t>(n)), on_line);
    }
  }
  const NmeaFramerStats& framer_stats() const { return framer_.stats(); }
  const SerialPortStats& port_stats() const { return port_->stats(); }

 private:
  std::unique_ptr<SerialPort> port_;
  NmeaFramer framer_;
  char chunk_[256];
};

// A sensor that speaks NMEA-style sentences on a serial line: the stream,
// the sentence decoder (latest(), stats()) and the stale limit.
template <typename Interface, typename Decoder, typename Sample>
class NmeaSerialSensor final : public Interface {
 public:
  NmeaSerialSensor(std::unique_ptr<SerialPort> port, const hal::Clock& clock, hal::Micros stale_after_us)
      : stream_(std::move(port)), clock_(clock), stale_after_us_(stale_after_us) {}

  Sample read() override {
    const hal::Micros now = clock_.now_us();
    stream_.poll([&](std::string_view line) { decoder_.decode(line, now); });
    Sample sample = decoder_.latest();
    if (sample.valid && now - sample.time_us > stale_after_us_) {
      sample.valid = false;
      ++stale_reads_;
    }
    return sample;
  }

  const SentenceStats& stats() const { return decoder_.stats(); }
  const NmeaSerialStream& stream() const { return stream_; }
  std::uint64_t stale_reads() const { return stale_reads_; }

 private:
  NmeaSerialStream stream_;
  Decoder decoder_;
  const hal::Clock& clock_;
  hal::Micros stale_after_us_;
  std::uint64_t stale_reads_ = 0;
};

using NmeaGpsReceiver = NmeaSerialSensor<hal::GpsReceiver, NmeaGpsDecoder, hal::GpsFix>;
using SerialCompass = NmeaSerialSensor<hal::AttitudeSensor, CompassDecoder, hal::AttitudeSample>;

}  // namespace glider::hal_linux
