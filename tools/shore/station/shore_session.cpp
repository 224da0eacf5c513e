// SPDX-License-Identifier: Apache-2.0
#include "shore_session.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <set>
#include <vector>

#include "console_link.hpp"
#include "glider_folders.hpp"
#include "received_files.hpp"
#include "session_journal.hpp"
#include "surfacing_event.hpp"
#include "zmodem_child.hpp"

namespace glider::shore {
namespace fs = std::filesystem;
namespace {

constexpr char kCtrlR = 0x12;  // resume the mission
// Seconds without a prompt after a Zmodem transfer before an empty line asks for one.
constexpr double kAfterTransferPokeS = 5.0;

// The gliders with a call in progress in this shore.
std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", seconds);
  return text;
}

class CallClaim {
 public:
  explicit CallClaim(std::string glider) : glider_(std::move(glider)) {
    const std::lock_guard<std::mutex> lock(mutex());
    owned_ = active().insert(glider_).second;
  }
  ~CallClaim() {
    if (!owned_) return;
    const std::lock_guard<std::mutex> lock(mutex());
    active().erase(glider_);
  }
  CallClaim(const CallClaim&) = delete;
  CallClaim& operator=(const CallClaim&) = delete;
  [[nodiscard]] bool owned() const { return owned_; }

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static std::set<std::string>& active() {
    static std::set<std::string> gliders;
    return gliders;
  }
  std::string glider_;
  bool owned_ = false;
};

class Call {
 public:
  Call(int fd, std::string peer, std::string call_stamp, unsigned call_number, const ShoreConfig& config,
       const std::atomic<bool>& stop, AfterSurfacingQueue& after)
      : config_(config),
        stop_(stop),
        after_(after),
        call_stamp_(std::move(call_stamp)),
        call_number_(call_number),
        link_(fd, journal_, config.max_line) {
    record_.peer = std::move(peer);
    record_.start_unix = now_unix();
  }

  void run() {
    journal_.write('*', "call from " + record_.peer);
    const Identity identity = identify();
    if (identity == Identity::kUnknown) {
      finish_unidentified();
      return;
    }
    if (identity == Identity::kNamedOnly) {
      finish();
      return;
    }
    try {
      // A glider makes one call at a time: a second one means the first is
      // dead but not yet noticed. Only one of them works on the queue.
      const CallClaim claim(record_.glider);
      if (!claim.owned()) {
        record_.notes.push_back("another call of this glider is in progress: queue and fetch left to it");
        journal_.write('*', record_.notes.back());
        linger();
      } else if (serve_commands() && send_files() && fetch_files()) {
        if (config_.resume_mission) link_.send_control(kCtrlR);
        linger();
      }
    } catch (const std::exception& error) {
      end(std::string("error: ") + error.what());
    }
    finish();
  }

 private:
  // Remaining seconds of the whole call, and of a wait capped by it.
  double call_left() const { return config_.call_timeout_s - (now_unix() - record_.start_unix); }
  double capped(double seconds) const { return std::max(0.0, std::min(seconds, call_left())); }

  void on_line(const std::string& line) {
    parse_dialog_line(line, record_.report);
    if (!record_.glider.empty() && record_.report.vehicle_name != record_.glider) {
      journal_.write('*', "the glider now says it is '" + record_.report.vehicle_name + "' (identified as '" +
                              record_.glider + "'): ignored");
      record_.report.vehicle_name = record_.glider;
    }
  }

  ConsoleLink::Event wait(double seconds, bool zmodem_ends_wait) {
    // Waits in slices so a shore shutdown ends the call promptly.
    const double until = now_unix() + capped(seconds);
    for (;;) {
      if (stop_) return ConsoleLink::Event::kClosed;
      const double left = until - now_unix();
      if (left <= 0.0) return ConsoleLink::Event::kTimeout;
      const ConsoleLink::Event event =
          link_.wait(std::min(left, 1.0), zmodem_ends_wait, [this](const std::string& line) { on_line(line); });
      if (event != ConsoleLink::Event::kTimeout) return event;
    }
  }

  // A prompt after a command; one empty line (the console answers it with a
  // new prompt) if the first went by unseen. After a transfer that is sooner:
  // the prompt may have gone to the Zmodem child in its last moments.
  bool wait_prompt(double poke_after_s = -1.0) {
    const double first =
        poke_after_s > 0.0 ? std::min(poke_after_s, config_.prompt_timeout_s / 2.0) : config_.prompt_timeout_s / 2.0;
    ConsoleLink::Event event = wait(first, false);
    if (event == ConsoleLink::Event::kTimeout) {
      link_.send_line("");
      event = wait(config_.prompt_timeout_s - first, false);
    }
    if (event == ConsoleLink::Event::kPrompt) return true;
    end(event == ConsoleLink::Event::kClosed ? (stop_ ? "shore stopped" : "hangup")
                                             : "no prompt within " + seconds_text(config_.prompt_timeout_s));
    return false;
  }

  void end(const std::string& reason) {
    if (record_.end_reason.empty()) record_.end_reason = reason;
    journal_.write('*', "end: " + reason);
  }

  enum class Identity { kReady, kNamedOnly, kUnknown };

  // kReady: named and at the prompt. kNamedOnly: the dialog named the glider
  // but the call ended or stalled before a prompt (its position is still
  // worth an event). kUnknown: never named.
  Identity identify() {
    const double deadline = now_unix() + config_.identify_timeout_s;
    int whoru_sent = 0;
    while (now_unix() < deadline) {
      const ConsoleLink::Event event = wait(deadline - now_unix(), false);
      if (event == ConsoleLink::Event::kClosed) {
        end(stop_ ? "shore stopped" : "hangup before identification");
        return adopt_name() ? Identity::kNamedOnly : Identity::kUnknown;
      }
      if (event != ConsoleLink::Event::kPrompt) break;
      // The dialog printed on connect names the glider; whoru asks it again.
      if (whoru_sent > 0 && adopt_name()) return Identity::kReady;
      if (whoru_sent >= 3) continue;
      link_.send_line("whoru");
      ++whoru_sent;
    }
    end("not identified within " + seconds_text(config_.identify_timeout_s));
    return adopt_name() ? Identity::kNamedOnly : Identity::kUnknown;
  }

  bool adopt_name() {
    if (record_.report.vehicle_name.empty()) return false;
    record_.glider = record_.report.vehicle_name;
    folders_ = glider_folders(config_.root, record_.glider, true);
    if (!call_id_.empty()) return true;  // already adopted and its journal claimed
    journal_.write('*', "identified: " + record_.glider);
    call_id_ = journal_.open_new(folders_.logs, call_stamp_, call_number_);
    record_.journal = call_id_ + ".journal";
    return true;
  }

  bool serve_commands() {
    for (;;) {
      const std::vector<std::string> queue = queued_commands(folders_);
      if (queue.empty()) return true;
      const std::string& command = queue.front();
      if (!link_.send_line(command)) {
        end("hangup");
        return false;
      }
      if (!wait_prompt()) return false;
      drop_first_command(folders_, command);
      record_.commands_sent.push_back(command);
    }
  }

  bool send_files() {
    for (const fs::path& file : queued_files(folders_)) {
      SentFile sent{file.filename().string(), static_cast<unsigned long long>(fs::file_size(file)), false};
      if (!link_.send_line("zr")) {
        end("hangup");
        return false;
      }
      const ConsoleLink::Event event = wait(config_.prompt_timeout_s, true);
      if (event != ConsoleLink::Event::kZmodem) {
        record_.notes.push_back("zr: the glider did not start receiving " + sent.name);
        record_.files_sent.push_back(sent);
        if (event == ConsoleLink::Event::kPrompt) continue;
        end(event == ConsoleLink::Event::kClosed ? "hangup" : "no zr answer");
        return false;
      }
      const ZmodemRun run = run_zmodem_child(
          {config_.sz_program, "-b", "-q", file.filename().string()}, file.parent_path(), link_.fd(),
          link_.take_pending(), config_.transfer_idle_timeout_s, capped(config_.transfer_timeout_s), stop_);
      journal_zmodem("send " + sent.name, run);
      link_.put_back(run.leftover);
      sent.delivered = run.exit_code == 0 && !run.carrier_lost && !run.timed_out && !run.stopped;
      if (sent.delivered) {
        fs::rename(file, folders_.sent / (utc_stamp(now_unix()) + "_" + sent.name));
      } else {
        record_.notes.push_back("sz " + sent.name + " failed (exit " + std::to_string(run.exit_code) +
                                "): kept in to-glider/ for the next call");
      }
      record_.files_sent.push_back(sent);
      if (run.carrier_lost || run.stopped) {
        end(run.stopped ? "shore stopped" : "carrier lost during transfer");
        return false;
      }
      if (!wait_prompt(kAfterTransferPokeS)) return false;
    }
    return true;
  }

  bool fetch_files() {
    if (config_.fetch.empty()) return true;
    std::string command = "send";
    for (const std::string& pattern : config_.fetch) command += " " + pattern;
    if (!link_.send_line(command)) {
      end("hangup");
      return false;
    }
    const ConsoleLink::Event event = wait(config_.prompt_timeout_s, true);
    if (event == ConsoleLink::Event::kPrompt) return true;  // nothing to send
    if (event != ConsoleLink::Event::kZmodem) {
      end(event == ConsoleLink::Event::kClosed ? "hangup" : "no answer to send");
      return false;
    }
    // -r: a file cut by a lost carrier last call resumes where it stopped.
    // (rz refuses names with "..": "Security Violation"; --restricted would
    // also refuse to append to the partial file, so it is not used.)
    const ZmodemRun run =
        run_zmodem_child({config_.rz_program, "-b", "-r", "-v"}, folders_.incoming, link_.fd(), link_.take_pending(),
                         config_.transfer_idle_timeout_s, capped(config_.transfer_timeout_s), stop_);
    journal_zmodem("receive", run);
    link_.put_back(run.leftover);
    for (const std::string& name : completed_receptions(run.diagnostics)) {
      try {
        const ReceivedFile file = publish_received(folders_, name, config_.cache_dirs);
        journal_.write('*', "received " + file.name + " (" + std::to_string(file.bytes) + " bytes, " + file.status +
                                (file.csv.empty() ? "" : ", " + file.csv) +
                                (file.csv_error.empty() ? "" : ", not converted: " + file.csv_error) + ")");
        record_.files_received.push_back(file);
      } catch (const std::exception& error) {
        record_.notes.push_back(std::string("publish: ") + error.what());
      }
    }
    record_.partial_files = partial_receptions(folders_);
    for (const std::string& name : record_.partial_files) journal_.write('*', "partial, kept for resume: " + name);
    if (run.carrier_lost || run.stopped) {
      end(run.stopped ? "shore stopped" : "carrier lost during transfer");
      return false;
    }
    if (run.exit_code != 0 || run.timed_out) {
      record_.notes.push_back("rz ended with exit " + std::to_string(run.exit_code) +
                              (run.timed_out ? " (transfer time limit)" : ""));
    }
    return wait_prompt(kAfterTransferPokeS);
  }

  void journal_zmodem(const std::string& what, const ZmodemRun& run) {
    journal_.write('*', "zmodem " + what + ": " + std::to_string(run.bytes_from_glider) + " bytes in, " +
                            std::to_string(run.bytes_to_glider) + " bytes out, exit " + std::to_string(run.exit_code) +
                            (run.carrier_lost ? ", carrier lost" : "") + (run.timed_out ? ", timed out" : ""));
  }

  // The glider hangs up when it dives; the shore keeps reading (and
  // journaling re-printed dialogs) until then, bounded.
  void linger() {
    const double until = now_unix() + capped(config_.linger_s);
    while (now_unix() < until) {
      const ConsoleLink::Event event = wait(until - now_unix(), false);
      if (event == ConsoleLink::Event::kClosed) {
        end(stop_ ? "shore stopped" : "hangup");
        return;
      }
    }
    end(call_left() <= 0.0 ? "call timeout" : "linger ended");
  }

  void finish() {
    record_.end_unix = now_unix();
    try {
      const std::string name = call_id_ + ".surfacing.json";
      write_file_atomically(folders_.logs / name, surfacing_event_json(record_));
      journal_.write('*', "event written: " + name);
      // Health and forecast run off this thread: the call (and its slot) ends now.
      after_.submit(folders_.base, journal_.path());
    } catch (const std::exception& error) {
      std::fprintf(stderr, "glider-shore: %s: event not written: %s\n", record_.glider.c_str(), error.what());
    }
  }

  void finish_unidentified() {
    try {
      const fs::path dir = config_.root / "unidentified";
      fs::create_directories(dir);
      call_id_ = journal_.open_new(dir, call_stamp_, call_number_);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "glider-shore: unidentified call journal: %s\n", error.what());
    }
  }

  const ShoreConfig& config_;
  const std::atomic<bool>& stop_;
  AfterSurfacingQueue& after_;
  std::string call_stamp_;  // UTC second the call came in
  unsigned call_number_;    // this process's count: the first NNNN tried
  std::string call_id_;     // STAMP_NNNN, claimed with the journal
  SessionJournal journal_;
  ConsoleLink link_;
  GliderFolders folders_;
  CallRecord record_;
};

}  // namespace

void serve_call(int fd, const std::string& peer, const ShoreConfig& config, const std::atomic<bool>& stop,
                AfterSurfacingQueue& after) {
  // Calls are numbered so two in the same second get different journals;
  // the number is only where the search for a free name starts (open_new).
  static std::atomic<unsigned> counter{0};
  try {
    Call call(fd, peer, utc_stamp(now_unix()), ++counter, config, stop, after);
    call.run();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "glider-shore: call from %s: %s\n", peer.c_str(), error.what());
  }
}

}  // namespace glider::shore
