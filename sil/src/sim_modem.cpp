// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/sim_modem.hpp"

#include <algorithm>
#include <cmath>

namespace glider::sil {
namespace {

constexpr double kGuardS = 1.0;  // "+++" needs this much silence either side (Hayes S12 default)

}  // namespace

SimModem::SimModem(const hal::Clock& clock, const LinkModel& link, FarEnd* far_end, std::uint64_t seed)
    : clock_(clock), link_(link), far_end_(far_end), random_(seed), last_tick_us_(clock.now_us()) {}

bool SimModem::link_down(double now_s) const {
  return link_.outage_from_s >= 0.0 && now_s >= link_.outage_from_s && now_s < link_.outage_to_s;
}

std::uint8_t SimModem::maybe_corrupt(std::uint8_t byte) {
  if (link_.corruption > 0.0 && random_.uniform() < link_.corruption) {
    ++stats_.corrupted;
    return static_cast<std::uint8_t>(byte ^ static_cast<std::uint8_t>(1u + random_.uniform() * 254.0));
  }
  return byte;
}

void SimModem::reply(const std::string& text) {
  const std::string framed = "\r\n" + text + "\r\n";
  to_glider_.insert(to_glider_.end(), framed.begin(), framed.end());
}

void SimModem::drop_call(bool tell_glider) {
  if (mode_ == Mode::kData && far_end_ != nullptr) far_end_->hangup(hal::to_seconds(clock_.now_us()));
  mode_ = Mode::kCommand;
  to_shore_.clear();
  escape_at_us_ = -1;
  if (tell_glider) reply("NO CARRIER");
}

void SimModem::tick() {
  const hal::Micros now = clock_.now_us();
  const double now_s = hal::to_seconds(now);
  const double dt_s = hal::to_seconds(now - last_tick_us_);
  last_tick_us_ = now;
  if (mode_ == Mode::kDialing && now >= dial_done_us_) {
    const bool answered =
        dial_will_connect_ && !link_down(now_s) && far_end_ != nullptr && far_end_->answer(dialled_, now_s);
    if (answered) {
      mode_ = Mode::kData;
      ++stats_.connects;
      up_credit_ = down_credit_ = 0.0;
      last_data_write_us_ = now;
      reply("CONNECT 19200");
    } else {
      mode_ = Mode::kCommand;
      reply("NO CARRIER");
    }
  }
  if (mode_ != Mode::kData || dt_s <= 0.0) return;
  // Carrier drops: Poisson over the elapsed time, and any outage.
  const double p_drop = 1.0 - std::exp(-link_.drops_per_hour * dt_s / 3600.0);
  if (link_down(now_s) || (link_.drops_per_hour > 0.0 && random_.uniform() < p_drop)) {
    ++stats_.drops;
    drop_call(true);
    return;
  }
  if (escape_at_us_ >= 0 && hal::to_seconds(now - escape_at_us_) >= kGuardS) {
    // Guard time after "+++" passed in silence: back to command mode, call still up.
    escape_at_us_ = -1;
    mode_ = Mode::kCommand;
    reply("OK");
    if (far_end_ != nullptr) far_end_->hangup(now_s);  // the firmware hangs up next (ATH)
    return;
  }
  // The link's byte rate, both ways.
  up_credit_ = std::min(up_credit_ + dt_s * link_.bytes_per_s, link_.bytes_per_s * 2.0);
  down_credit_ = std::min(down_credit_ + dt_s * link_.bytes_per_s, link_.bytes_per_s * 2.0);
  std::vector<std::uint8_t> up;
  while (up_credit_ >= 1.0 && !to_shore_.empty()) {
    up.push_back(maybe_corrupt(to_shore_.front()));
    to_shore_.pop_front();
    up_credit_ -= 1.0;
  }
  if (!up.empty() && far_end_ != nullptr) {
    stats_.bytes_up += up.size();
    far_end_->receive(up, now_s);
  }
  if (far_end_ != nullptr && down_credit_ >= 1.0) {
    const std::vector<std::uint8_t> down = far_end_->take(static_cast<std::size_t>(down_credit_), now_s);
    for (const std::uint8_t b : down) to_glider_.push_back(maybe_corrupt(b));
    down_credit_ -= static_cast<double>(down.size());
    stats_.bytes_down += down.size();
  }
}

std::size_t SimModem::read(std::span<std::uint8_t> buffer) {
  tick();
  const std::size_t n = std::min(buffer.size(), to_glider_.size());
  std::copy_n(to_glider_.begin(), n, buffer.begin());
  to_glider_.erase(to_glider_.begin(), to_glider_.begin() + static_cast<std::ptrdiff_t>(n));
  return n;
}

std::size_t SimModem::write(std::span<const std::uint8_t> bytes) {
  tick();
  const hal::Micros now = clock_.now_us();
  if (mode_ == Mode::kData) {
    const bool escape = bytes.size() == 3 && bytes[0] == '+' && bytes[1] == '+' && bytes[2] == '+' &&
                        hal::to_seconds(now - last_data_write_us_) >= kGuardS;
    if (escape) {
      escape_at_us_ = now;
      return 3;
    }
    escape_at_us_ = -1;  // data after "+++" within the guard: it was data
    const std::size_t room = link_.tx_buffer_bytes > to_shore_.size() ? link_.tx_buffer_bytes - to_shore_.size() : 0;
    const std::size_t n = std::min(room, bytes.size());
    to_shore_.insert(to_shore_.end(), bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(n));
    if (n > 0) last_data_write_us_ = now;
    return n;
  }
  for (const std::uint8_t b : bytes) {
    if (mode_ == Mode::kDialing) {
      // Any character aborts a dial in progress (Hayes).
      mode_ = Mode::kCommand;
      reply("NO CARRIER");
      continue;
    }
    if (echo_) to_glider_.push_back(b);
    if (b == '\r') {
      command(line_);
      line_.clear();
    } else if (b != '\n' && line_.size() < 256) {
      line_.push_back(static_cast<char>(b));
    }
  }
  return bytes.size();
}

void SimModem::command(const std::string& raw) {
  std::string line = raw;
  std::transform(line.begin(), line.end(), line.begin(), [](unsigned char c) { return std::toupper(c); });
  const double now_s = hal::to_seconds(clock_.now_us());
  if (line == "AT") {
    reply("OK");
  } else if (line == "ATE0" || line == "ATE1") {
    echo_ = line == "ATE1";
    reply("OK");
  } else if (line == "AT+CSQ") {
    int csq = 0;
    if (!link_down(now_s) && random_.uniform() < link_.availability)
      csq = 1 + static_cast<int>(random_.uniform() * 5.0);
    reply("+CSQ:" + std::to_string(std::min(csq, 5)));
    reply("OK");
  } else if (line.rfind("ATD", 0) == 0 && line.size() > 3) {
    ++stats_.calls;
    dialled_ = raw.substr(3);
    mode_ = Mode::kDialing;
    dial_will_connect_ = random_.uniform() < link_.connect_probability;
    const double setup = link_.call_setup_s + link_.call_setup_jitter_s * random_.uniform();
    dial_done_us_ = clock_.now_us() + static_cast<hal::Micros>(setup * 1e6);
  } else if (line == "ATH" || line == "ATH0") {
    if (far_end_ != nullptr && mode_ == Mode::kData) far_end_->hangup(now_s);
    mode_ = Mode::kCommand;
    reply("OK");
  } else if (line.empty()) {
    // a bare CR: nothing
  } else {
    reply("ERROR");
  }
}

void SimModem::end_of_cycle(bool listening) {
  if (mode_ == Mode::kData && listening && to_shore_.empty() && far_end_ != nullptr) far_end_->settle();
}

hal::Carrier SimModem::carrier() const {
  if (!link_.dcd_wired) return hal::Carrier::kUnknown;
  return mode_ == Mode::kData ? hal::Carrier::kPresent : hal::Carrier::kLost;
}

}  // namespace glider::sil
