// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include "glider/firmware/comms/file_access.hpp"
#include "glider/firmware/comms/zmodem_file_info.hpp"
#include "glider/firmware/comms/zmodem_session.hpp"

namespace glider::fw::comms::zmodem {

// Zmodem receiver (shore -> glider: mission files). Each file is written to
// a temporary name "<name>.<length>-<mtime>.zpart" and renamed to <name> only
// after ZEOF at exactly the announced length, every subpacket's CRC having
// been checked: a partial upload never appears under its real name. A later
// session offered the same file (same name, length and mtime) resumes from
// the partial's size (ZRPOS), the specification's crash recovery.
// Non-blocking: step() reads and writes at most `budget` bytes each.
class Receiver : public Session {
 public:
  static constexpr std::size_t kMaxResults = 16;
  struct Result {
    FileInfo info;
    bool published = false;  // complete and renamed to its real name
  };

  Receiver(ByteStream& stream, FileAccess& files, const Options& options = {})
      : Session(stream, options), files_(files) {
    parser_.set_drop_control(options.escape_control);
  }

  void start(hal::Micros now);
  Status step(hal::Micros now, std::size_t budget);
  // Cancels the session (5+ CAN to the peer); a partial file is kept for resume.
  void abort();

  std::size_t result_count() const { return result_count_; }
  const Result& result(std::size_t i) const { return results_[i]; }
  // Offset reached in the file being received.
  std::int64_t offset() const { return offset_; }

 private:
  enum class State : std::uint8_t { wait_file, file_info, receiving, finishing };
  void on_event(Parser::Event event, std::uint8_t byte, hal::Micros now);
  void on_header(const Header& header, hal::Micros now);
  void on_subpacket(hal::Micros now);
  void on_timeout(hal::Micros now);
  void open_file(hal::Micros now);
  void finish_file(hal::Micros now);
  void close_partial();
  void send(const Header& header);
  void send_fin();  // our ZFIN at the session's end, XON first
  Header rinit() const;
  void record(bool published);

  FileAccess& files_;
  State state_ = State::wait_file;
  Frame data_for_ = Frame::rqinit;  // the header whose subpackets are arriving
  bool accepting_ = false;          // data at offset_ is being taken
  bool file_open_ = false;
  int o_count_ = 0;  // 'O's of the sender's "OO" after ZFIN
  // When our ZFIN is said again if no "OO" has come (finishing), how often,
  // and how many more times. Like lrzsz's rz (ackbibi: ZFIN up to 3 times):
  // our answer and one repeat both vanished (lead-ins garbled) and sz, which
  // waits silently for a ZFIN (saybibi, tens of seconds), never exited.
  static constexpr int kFinRepeats = 2;
  hal::Micros fin_again_us_ = 0;
  hal::Micros fin_interval_us_ = 0;
  int fin_repeats_left_ = 0;
  // The link's round trip (smoothed), measured from a ZRPOS/ZRINIT/ZNAK to the next header:
  // how long the sender's "OO" may take to arrive after our ZFIN.
  hal::Micros now_ = 0;
  // A ZRPOS/ZRINIT/ZNAK waiting for its answer since; a repeated one is not
  // timed (Karn's rule: its answer's delay includes the lost first one, and
  // a round trip grown so made every later repeat wait 4 x 2 s).
  static constexpr hal::Micros kNotAsked = -1;
  static constexpr hal::Micros kRepeated = -2;
  hal::Micros asked_us_ = kNotAsked;
  hal::Micros round_trip_us_ = 0;
  // A ZRPOS not yet obeyed (no ZDATA at offset_ since): said again at
  // resync_at_us_ (-1: none), after 4 round trips (at least kMinResyncUs),
  // doubling, never beyond the timeout. A garbled ZRPOS would otherwise cost
  // the whole timeout while the sender streams on or waits (lrzsz's sz).
  static constexpr hal::Micros kMinResyncUs = 500'000;
  hal::Micros resync_at_us_ = -1;
  hal::Micros resync_interval_us_ = 0;
  hal::Micros heard_us_ = 0;  // the last byte from the sender
  bool sender_seen_ = false;  // a ZRQINIT came, or a file ended: a silence now is a lost header
  // Waiting for a whole ZFILE: after ours (file_info), or after a file's end
  // (the sender's next ZFILE or ZFIN, or our ZRINIT, may have been lost).
  bool between_files() const { return state_ == State::file_info || (state_ == State::wait_file && sender_seen_); }
  void resync(hal::Micros now);
  FileInfo info_;
  std::array<char, kMaxName + 56> temp_name_{};
  std::int64_t offset_ = 0;
  std::array<Result, kMaxResults> results_{};
  std::size_t result_count_ = 0;
};

}  // namespace glider::fw::comms::zmodem
