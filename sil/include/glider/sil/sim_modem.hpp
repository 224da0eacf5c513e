// SPDX-License-Identifier: Apache-2.0
#pragma once
// A simulated Iridium-class modem for SIL: it speaks Hayes AT itself (AT,
// ATE0/1, AT+CSQ, ATD, ATH, the "+++" guard-time escape) and carries a call
// over a seeded link model (satellite availability, call set-up time,
// Iridium's byte rate, carrier drops, byte corruption) to a pluggable far
// end: an in-process fake shore (tests) or a real shore station over TCP
// (`glider-sil --shore HOST:PORT`). Time is the SIL clock; two runs with the
// same seed give the same bytes (with the in-process far end).
#include <cstdint>
#include <deque>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "glider/hal/clock.hpp"
#include "glider/hal/modem.hpp"
#include "glider/sil/portable_random.hpp"

namespace glider::sil {

struct LinkModel {
  // Probability that the sky is usable at a signal query (CSQ 1..5, else 0).
  double availability = 0.9;
  double call_setup_s = 12.0;  // ATD to CONNECT, plus up to call_setup_jitter_s
  double call_setup_jitter_s = 8.0;
  double connect_probability = 0.9;  // a usable sky still fails some calls: NO CARRIER
  double bytes_per_s = 270.0;        // Iridium data: 2400 bit/s, ~250-300 B/s of payload
  double drops_per_hour = 0.5;       // carrier drops while connected (Poisson)
  double corruption = 0.0;           // probability each byte is corrupted (both directions)
  // A window of simulated time with no link at all (CSQ 0, calls fail): tests.
  double outage_from_s = -1.0;
  double outage_to_s = -1.0;
  std::size_t tx_buffer_bytes = 2048;  // the modem's own buffer: write() takes what fits
  bool dcd_wired = true;               // false: carrier() says kUnknown (only "NO CARRIER" tells)
};

// The shore side of a call.
class FarEnd {
 public:
  virtual ~FarEnd() = default;
  // The modem dialled `number`: true answers (CONNECT), false does not (NO CARRIER).
  virtual bool answer(const std::string& number, double now_s) = 0;
  // Bytes from the glider, as they arrive at the shore.
  virtual void receive(std::span<const std::uint8_t> bytes, double now_s) = 0;
  // Bytes the shore wants to send now (at most `max`).
  virtual std::vector<std::uint8_t> take(std::size_t max, double now_s) = 0;
  virtual void hangup(double now_s) = 0;
  // The end of a cycle in which everything the glider wrote has reached the
  // shore and the glider listens for an answer: a far end that answers in
  // wall time (TcpShore) may wait for it here, so that its thinking costs no
  // simulated time. In-process far ends answer at once: nothing to wait for.
  virtual void settle() {}
};

struct SimModemStats {
  std::uint32_t calls = 0;
  std::uint32_t connects = 0;
  std::uint32_t drops = 0;
  std::uint64_t bytes_up = 0;    // glider to shore
  std::uint64_t bytes_down = 0;  // shore to glider
  std::uint64_t corrupted = 0;
};

class SimModem final : public hal::Modem {
 public:
  SimModem(const hal::Clock& clock, const LinkModel& link, FarEnd* far_end, std::uint64_t seed);

  std::size_t read(std::span<std::uint8_t> buffer) override;
  std::size_t write(std::span<const std::uint8_t> bytes) override;
  hal::Carrier carrier() const override;

  const SimModemStats& stats() const { return stats_; }
  bool in_call() const { return mode_ == Mode::kData; }
  // Called by the SIL loop after each cycle: `listening` = the glider waits
  // for the shore's input (its dialog). Lets the far end settle (FarEnd::settle)
  // once the glider's bytes have all gone up the link.
  void end_of_cycle(bool listening);

 private:
  enum class Mode { kCommand, kDialing, kData };

  void tick();
  void command(const std::string& line);
  void reply(const std::string& text);
  void drop_call(bool tell_glider);
  bool link_down(double now_s) const;
  std::uint8_t maybe_corrupt(std::uint8_t byte);

  const hal::Clock& clock_;
  LinkModel link_;
  FarEnd* far_end_;
  PortableRandom random_;
  Mode mode_ = Mode::kCommand;
  bool echo_ = true;
  std::string line_;
  std::deque<std::uint8_t> to_glider_;
  std::deque<std::uint8_t> to_shore_;
  hal::Micros dial_done_us_ = 0;
  bool dial_will_connect_ = false;
  std::string dialled_;
  hal::Micros last_tick_us_ = 0;
  double up_credit_ = 0.0;
  double down_credit_ = 0.0;
  hal::Micros last_data_write_us_ = 0;
  hal::Micros escape_at_us_ = -1;
  SimModemStats stats_;
};

// The in-process shore of the tests: answers (unless told not to), records
// every byte it receives and types scripted input at set times after the
// connect.
class FakeShore final : public FarEnd {
 public:
  struct Typed {
    double after_connect_s;
    std::string text;
  };
  bool listening = true;
  std::vector<std::string> dead_numbers;  // calls to these are never answered
  std::vector<Typed> script;              // typed in every call, relative to its CONNECT

  bool answer(const std::string& number, double now_s) override;
  void receive(std::span<const std::uint8_t> bytes, double now_s) override;
  std::vector<std::uint8_t> take(std::size_t max, double now_s) override;
  void hangup(double now_s) override;

  const std::string& transcript() const { return transcript_; }
  std::uint32_t calls() const { return calls_; }
  std::uint32_t hangups() const { return hangups_; }
  const std::vector<std::string>& numbers() const { return numbers_; }

 private:
  std::string transcript_;
  std::uint32_t calls_ = 0;
  std::uint32_t hangups_ = 0;
  std::vector<std::string> numbers_;
  double connect_s_ = 0.0;
  std::size_t next_ = 0;
  std::deque<std::uint8_t> pending_;
  bool connected_ = false;
};

// A real shore station over TCP (RUDICS: the call is a TCP connection).
// Connects at answer() (bounded wait), then relays bytes both ways without
// blocking. The shore answers in wall time while SIL's clock is simulated,
// so the call is paced in lockstep with the shore's answers: at the end of a
// cycle in which the glider listens and has nothing left to send, settle()
// waits (wall time, at most `answer_wait_ms`) for the shore's next byte if
// the glider spoke last (a command's answer, a Zmodem header, the next typed
// line are due) or the shore was still talking (a stream paused by the
// shore's own work: a child started, a file read). The shore's thinking then
// costs no simulated time, however loaded the machine, up to that bound; a
// shore with nothing to say costs the bound once per silence
// (docs/comms.md, End to end).
class TcpShore final : public FarEnd {
 public:
  static constexpr int kDefaultAnswerWaitMs = 10000;
  TcpShore(std::string host, int port, int answer_wait_ms = kDefaultAnswerWaitMs);
  ~TcpShore() override;
  TcpShore(const TcpShore&) = delete;
  TcpShore& operator=(const TcpShore&) = delete;

  bool answer(const std::string& number, double now_s) override;
  void receive(std::span<const std::uint8_t> bytes, double now_s) override;
  std::vector<std::uint8_t> take(std::size_t max, double now_s) override;
  void hangup(double now_s) override;
  void settle() override;
  const std::string& last_error() const { return error_; }
  // Waits that ended without a byte from the shore (each cost answer_wait_ms).
  std::uint32_t unanswered_waits() const { return unanswered_waits_; }
  std::uint32_t waits() const { return waits_; }

 private:
  std::string host_;
  int port_;
  int answer_wait_ms_;
  int fd_ = -1;
  bool answer_due_ = false;         // the glider spoke last: the shore has not answered yet
  bool shore_was_talking_ = false;  // the last take() got bytes
  std::uint32_t waits_ = 0;
  std::uint32_t unanswered_waits_ = 0;
  std::string error_;
};

// `HOST`, `HOST:PORT` or `:PORT` (the shore station's default port 6565,
// host 127.0.0.1). False with `error` set on a bad port.
inline constexpr int kDefaultShorePort = 6565;
bool parse_shore_address(const std::string& text, std::string& host, int& port, std::string& error);

}  // namespace glider::sil
