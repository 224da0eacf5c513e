// SPDX-License-Identifier: Apache-2.0
// The Zmodem engine against Debian's lrzsz over a pseudo-terminal pair: the
// engine sends to `rz` or receives from `sz`, through a relay that can
// corrupt bytes (seeded; the seed is printed) or drop the carrier part way
// (then a second session must resume). Files are random bytes of the given
// sizes, compared byte for byte. Prints the throughput and the longest
// step() call. Exit 0 pass, 1 fail, 77 skipped (no lrzsz), 2 usage.
//
//   zmodem_lrzsz --direction to-rz|from-sz [--sizes 0,1,1024] [--corruption P]
//                [--seed N] [--cut-after BYTES] [--escape] [--limit-s S] [--fin-xoff K]
//                [--fin-lose N]
//
// --fin-xoff K: the engine's first ZFIN header reaches the peer with its byte
// K (6-19; 0 is the first ZPAD, 19 the closing LF) turned into XOFF, the one garbling that stops lrzsz's
// tty (IXON): a deterministic replay of a 1-in-255 corruption at session end.
// --fin-lose N: the engine's first N hex ZFIN headers reach the peer with
// their 'B' (byte 3) garbled: lrzsz's zgethdr sees no header in them and
// waits on in silence (sz's saybibi: tens of seconds), the way a ZFIN whose
// lead-in a 1 % corruption hit is lost.
#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "glider/firmware/comms/file_access_posix.hpp"
#include "glider/firmware/comms/zmodem_parser.hpp"
#include "glider/firmware/comms/zmodem_receiver.hpp"
#include "glider/firmware/comms/zmodem_sender.hpp"

namespace fs = std::filesystem;
using namespace glider::fw::comms;
using namespace glider::fw::comms::zmodem;

namespace {

glider::hal::Micros now_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// ZMODEM_TRACE=FILE: every header and subpacket end each side decodes from what
// reaches it (after the relay's corruption), with its time: where a stall
// starts is then readable (which header went unanswered, which was garbled).
class Trace {
 public:
  Trace() {
    const char* path = std::getenv("ZMODEM_TRACE");
    if (path != nullptr) out_ = std::fopen(path, "w");
  }
  ~Trace() {
    if (out_ != nullptr) std::fclose(out_);
  }
  void bytes(const char* to, Parser& parser, std::span<const std::uint8_t> data) {
    if (out_ == nullptr) return;
    for (const std::uint8_t b : data) {
      const Parser::Event e = parser.feed(b);
      if (e == Parser::Event::none) continue;
      const double t = static_cast<double>(now_us() - start_) / 1e6;
      if (e == Parser::Event::header) {
        std::fprintf(out_, "%9.3f to %s header %d pos %u\n", t, to, static_cast<int>(parser.header().type),
                     parser.header().position());
      } else if (e == Parser::Event::subpacket) {
        std::fprintf(out_, "%9.3f to %s subpacket %zu end %c\n", t, to, parser.data().size(), parser.end());
      } else {
        std::fprintf(out_, "%9.3f to %s %s\n", t, to,
                     e == Parser::Event::bad_header      ? "BAD HEADER"
                     : e == Parser::Event::bad_subpacket ? "BAD SUBPACKET"
                                                         : "CANCEL");
      }
    }
  }
  void note(const char* what) {
    if (out_ != nullptr) std::fprintf(out_, "%9.3f %s\n", static_cast<double>(now_us() - start_) / 1e6, what);
  }
  Parser to_engine, to_peer;

 private:
  std::FILE* out_ = nullptr;
  glider::hal::Micros start_ = now_us();
};

// The pty master as a ByteStream, with the relay's faults: each byte in
// either direction is corrupted with probability p (xor with 1..255), and
// after cut_after bytes in all the carrier is gone (nothing passes).
class RelayStream : public ByteStream {
 public:
  RelayStream(int fd, double corruption, std::uint64_t seed, std::uint64_t cut_after, int fin_xoff, int fin_lose)
      : fd_(fd), corruption_(corruption), rng_(seed), cut_after_(cut_after), fin_xoff_(fin_xoff), fin_lose_(fin_lose) {}
  std::size_t read(std::span<std::uint8_t> out) override {
    const ssize_t n = ::read(fd_, out.data(), out.size());
    if (n <= 0) return 0;
    auto count = static_cast<std::size_t>(n);
    if (carried_ >= cut_after_) return 0;
    carried_ += count;
    for (std::size_t i = 0; i < count; ++i) out[i] = noisy(out[i]);
    trace_.bytes("engine", trace_.to_engine, out.first(count));
    return count;
  }
  std::size_t write(std::span<const std::uint8_t> data) override {
    if (carried_ >= cut_after_) return data.size();  // into the void
    std::vector<std::uint8_t>& buf = scratch_;
    buf.assign(data.begin(), data.end());
    const std::size_t lost_at = fin_lose(buf);
    // Corrupt once per byte offered; bytes the pty refuses are offered
    // again next time, so their fate is drawn again (a fresh transmission).
    for (auto& b : buf) b = fin_xoff(noisy(b));
    const ssize_t n = ::write(fd_, buf.data(), buf.size());
    if (lost_at < buf.size() && (n <= 0 || lost_at >= static_cast<std::size_t>(n))) ++fin_lose_;  // not out: again
    if (n <= 0) return 0;
    trace_.bytes("peer", trace_.to_peer, std::span<const std::uint8_t>(buf.data(), static_cast<std::size_t>(n)));
    carried_ += static_cast<std::size_t>(n);
    return static_cast<std::size_t>(n);
  }
  std::uint64_t corrupted() const { return corrupted_; }

 private:
  std::uint8_t noisy(std::uint8_t b) {
    if (corruption_ <= 0.0 || uniform_(rng_) >= corruption_) return b;
    ++corrupted_;
    return static_cast<std::uint8_t>(b ^ flip_(rng_));
  }
  // The first hex ZFIN header wholly in `buf` gets its 'B' garbled while
  // fin_lose_ lasts; returns the garbled byte's index (buf.size(): none).
  std::size_t fin_lose(std::vector<std::uint8_t>& buf) {
    static constexpr std::array<std::uint8_t, 6> kFinStart = {kPad, kPad, kDle, kHex, '0', '8'};
    if (fin_lose_ <= 0) return buf.size();
    const auto at = std::search(buf.begin(), buf.end(), kFinStart.begin(), kFinStart.end());
    if (at == buf.end()) return buf.size();
    --fin_lose_;
    ++corrupted_;
    const auto index = static_cast<std::size_t>(at - buf.begin()) + 3;
    buf[index] = static_cast<std::uint8_t>(kHex ^ 0x20);  // 'b': no frame kind
    return index;
  }
  // The engine's bytes to the peer, in order: the first hex ZFIN header
  // ("**" ZDLE 'B' "08") is found as it goes by and its byte fin_xoff_ made XOFF.
  std::uint8_t fin_xoff(std::uint8_t b) {
    if (fin_xoff_ < 0) return b;
    static constexpr std::array<std::uint8_t, 6> kFinStart = {kPad, kPad, kDle, kHex, '0', '8'};
    if (fin_at_ >= 0) {
      ++fin_at_;
      if (fin_at_ != fin_xoff_) return b;
      fin_xoff_ = -1;  // once
      ++corrupted_;
      return kXoff;
    }
    std::copy(recent_.begin() + 1, recent_.end(), recent_.begin());
    recent_.back() = b;
    if (recent_ == kFinStart) {
      // The header's first 6 bytes are already out: only a later byte can be hit.
      fin_at_ = static_cast<int>(kFinStart.size()) - 1;
      if (fin_xoff_ < static_cast<int>(kFinStart.size())) fin_xoff_ = -1;
    }
    return b;
  }
  int fd_;
  double corruption_;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  std::uniform_int_distribution<int> flip_{1, 255};
  std::uint64_t cut_after_;
  std::uint64_t carried_ = 0;
  std::uint64_t corrupted_ = 0;
  int fin_xoff_;                          // -1: no ZFIN garbled
  int fin_lose_;                          // ZFIN headers still to be lost
  int fin_at_ = -1;                       // the index of the byte going out in the first ZFIN
  std::array<std::uint8_t, 6> recent_{};  // the last bytes to the peer, before corruption
  std::vector<std::uint8_t> scratch_;
  Trace trace_;
};

// The glider's file store, timed: the longest single call (close() fsyncs)
// shows how much of the longest step is the store's and not the engine's.
class TimedFiles : public FileAccess {
 public:
  explicit TimedFiles(FileAccess& inner) : inner_(inner) {}
  glider::hal::Micros longest_us = 0;
  template <typename F>
  auto timed(F&& f) {
    const auto t0 = now_us();
    auto r = f();
    longest_us = std::max(longest_us, now_us() - t0);
    return r;
  }
  std::int64_t size(std::string_view n) override {
    return timed([&] { return inner_.size(n); });
  }
  std::int64_t mtime(std::string_view n) override {
    return timed([&] { return inner_.mtime(n); });
  }
  bool open(std::string_view n, Mode m) override {
    return timed([&] { return inner_.open(n, m); });
  }
  bool seek(std::int64_t o) override {
    return timed([&] { return inner_.seek(o); });
  }
  std::size_t read(std::span<std::uint8_t> out) override {
    return timed([&] { return inner_.read(out); });
  }
  bool write(std::span<const std::uint8_t> d) override {
    return timed([&] { return inner_.write(d); });
  }
  bool close() override {
    return timed([&] { return inner_.close(); });
  }
  bool rename(std::string_view a, std::string_view b) override {
    return timed([&] { return inner_.rename(a, b); });
  }
  bool remove(std::string_view n) override {
    return timed([&] { return inner_.remove(n); });
  }

 private:
  FileAccess& inner_;
};

struct Peer {
  pid_t pid = -1;
  int master = -1;
};

Peer spawn(const std::vector<std::string>& argv, const fs::path& dir) {
  Peer peer;
  int slave = -1;
  if (openpty(&peer.master, &slave, nullptr, nullptr, nullptr) != 0) return peer;
  termios raw{};
  tcgetattr(slave, &raw);
  cfmakeraw(&raw);
  tcsetattr(slave, TCSANOW, &raw);
  peer.pid = fork();
  if (peer.pid == 0) {
    setsid();
    ioctl(slave, TIOCSCTTY, 0);
    dup2(slave, 0);
    dup2(slave, 1);
    // lrzsz's own account (-vv) goes to peer.log beside the folders.
    const int log_fd = ::open((dir.parent_path() / "peer.log").c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    dup2(log_fd, 2);
    ::close(peer.master);
    ::close(slave);
    if (chdir(dir.c_str()) != 0) _exit(126);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
  ::close(slave);
  fcntl(peer.master, F_SETFL, fcntl(peer.master, F_GETFL) | O_NONBLOCK);
  return peer;
}

// Waits up to `seconds` for the peer; kills it after. Returns its exit code (-1 killed).
int reap(Peer& peer, double seconds) {
  int status = 0;
  const auto end = now_us() + static_cast<glider::hal::Micros>(seconds * 1e6);
  while (now_us() < end) {
    if (waitpid(peer.pid, &status, WNOHANG) == peer.pid) {
      ::close(peer.master);
      return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    usleep(10000);
  }
  kill(peer.pid, SIGKILL);
  waitpid(peer.pid, &status, 0);
  ::close(peer.master);
  return -1;
}

std::vector<std::uint8_t> read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

struct Args {
  std::string direction;
  std::vector<std::size_t> sizes{0, 1, 1024, 300 * 1024};
  double corruption = 0.0;
  std::uint64_t seed = 1;
  std::uint64_t cut_after = UINT64_MAX;
  bool escape = false;
  double limit_s = 50.0;
  std::uint32_t block = kMaxBlock;
  int fin_xoff = -1;
  int fin_lose = 0;
};

struct SessionResult {
  Status status = Status::idle;
  Failure failure = Failure::none;
  int peer_exit = 0;
  double seconds = 0.0;
  glider::hal::Micros max_step_us = 0;
  std::uint64_t steps = 0;
  std::uint64_t link_bytes = 0;  // both directions, as the engine counted them
};

// One session: the engine (sender or receiver) against sz or rz.
template <typename Engine>
SessionResult run_session(Engine& engine, Peer& peer, RelayStream& relay, double limit_s, bool cut) {
  SessionResult result;
  const auto start = now_us();
  engine.start(start);
  constexpr std::size_t kBudget = 4096;  // bytes per step and direction
  while (true) {
    const auto before = now_us();
    const Status status = engine.step(before, kBudget);
    const auto after = now_us();
    result.max_step_us = std::max(result.max_step_us, after - before);
    ++result.steps;
    if (status != Status::running) break;
    if (static_cast<double>(after - start) > limit_s * 1e6) {
      engine.abort();
      break;
    }
    // The control loop's cycle, shortened: wait for the link at most 1 ms.
    pollfd pfd{peer.master, POLLIN, 0};
    if (poll(&pfd, 1, 1) > 0 && (pfd.revents & POLLIN) == 0) usleep(1000);  // hung up: no busy loop
  }
  result.link_bytes = engine.bytes_in() + engine.bytes_out();
  result.status = engine.status();
  result.failure = engine.failure();
  result.seconds = static_cast<double>(now_us() - start) / 1e6;
  (void)relay;
  if (cut) kill(peer.pid, SIGHUP);  // the carrier is gone: the shore's rz/sz is hung up on
  result.peer_exit = reap(peer, cut ? 2.0 : 15.0);
  return result;
}

void print(const char* what, const SessionResult& r, std::uint64_t payload, const RelayStream& relay) {
  std::printf(
      "%s: engine %s (%s), peer exit %d, %.2f s, %.1f KiB/s payload, %llu steps, longest step %lld us, "
      "%llu bytes corrupted\n",
      what, r.status == Status::done ? "done" : "failed", failure_name(r.failure), r.peer_exit, r.seconds,
      static_cast<double>(payload) / 1024.0 / std::max(r.seconds, 1e-6), static_cast<unsigned long long>(r.steps),
      static_cast<long long>(r.max_step_us), static_cast<unsigned long long>(relay.corrupted()));
}

int usage() {
  std::fprintf(stderr,
               "usage: zmodem_lrzsz --direction to-rz|from-sz [--sizes 0,1,1024] [--corruption P] [--seed N]\n"
               "                    [--cut-after BYTES] [--escape] [--limit-s S] [--fin-xoff K] [--fin-lose N]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  for (int i = 1; i < argc; ++i) {
    const std::string key = argv[i];
    if (key == "--escape") {
      args.escape = true;
      continue;
    }
    if (i + 1 >= argc) return usage();
    const std::string value = argv[++i];
    if (key == "--direction") {
      args.direction = value;
    } else if (key == "--sizes") {
      args.sizes.clear();
      for (std::size_t pos = 0; pos <= value.size();) {
        const std::size_t comma = std::min(value.find(',', pos), value.size());
        args.sizes.push_back(std::stoull(value.substr(pos, comma - pos)));
        pos = comma + 1;
      }
    } else if (key == "--corruption") {
      args.corruption = std::stod(value);
    } else if (key == "--seed") {
      args.seed = std::stoull(value);
    } else if (key == "--cut-after") {
      args.cut_after = std::stoull(value);
    } else if (key == "--block") {
      args.block = static_cast<std::uint32_t>(std::stoul(value));
    } else if (key == "--fin-xoff") {
      // Bytes 0-5 ("**" ZDLE 'B' "08") are how the header is recognised, and
      // so already out; 19 is its LF, the last.
      args.fin_xoff = std::stoi(value);
      if (args.fin_xoff < 6 || args.fin_xoff > 19) {
        std::fprintf(stderr,
                     "zmodem_lrzsz: --fin-xoff %s: allowed 6 to 19 (a byte of the hex ZFIN after \"**\" ZDLE B 08)\n",
                     value.c_str());
        return 2;
      }
    } else if (key == "--fin-lose") {
      args.fin_lose = std::stoi(value);
      if (args.fin_lose < 0 || args.fin_lose > 10) {
        std::fprintf(stderr, "zmodem_lrzsz: --fin-lose %s: allowed 0 to 10 (ZFIN headers lost)\n", value.c_str());
        return 2;
      }
    } else if (key == "--limit-s") {
      args.limit_s = std::stod(value);
    } else {
      return usage();
    }
  }
  if (args.direction != "to-rz" && args.direction != "from-sz") return usage();
  const bool to_rz = args.direction == "to-rz";
  if (std::system(to_rz ? "command -v rz >/dev/null 2>&1" : "command -v sz >/dev/null 2>&1") != 0) {
    std::printf("SKIPPED: lrzsz (%s) is not installed (Debian package lrzsz)\n", to_rz ? "rz" : "sz");
    return 77;
  }
  signal(SIGPIPE, SIG_IGN);
  std::printf("direction %s, seed %llu, corruption %.3f, cut after %llu bytes, escape %d\n", args.direction.c_str(),
              static_cast<unsigned long long>(args.seed), args.corruption,
              static_cast<unsigned long long>(args.cut_after), args.escape ? 1 : 0);

  char dir_template[] = "/tmp/zmodem_lrzsz.XXXXXX";
  if (mkdtemp(dir_template) == nullptr) return 1;
  const fs::path root(dir_template);
  const fs::path from_dir = root / "from";  // the sender's folder
  const fs::path to_dir = root / "to";      // the receiver's folder
  fs::create_directories(from_dir);
  fs::create_directories(to_dir);
  std::mt19937_64 rng(args.seed);
  std::vector<std::string> names;
  std::uint64_t payload = 0;
  for (std::size_t i = 0; i < args.sizes.size(); ++i) {
    std::vector<std::uint8_t> data(args.sizes[i]);
    for (auto& b : data) b = static_cast<std::uint8_t>(rng());
    char name[64];
    std::snprintf(name, sizeof name, "f%zu-%zu.bin", i, args.sizes[i]);
    names.emplace_back(name);
    std::ofstream(from_dir / names.back(), std::ios::binary)
        .write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
    payload += data.size();
  }

  Options options;
  options.escape_control = args.escape;
  options.max_block = args.block;
  // The defaults (10 s, 10 repeats): lrzsz's own timeouts are 10 s, and sz
  // waits for 5 s of silence after a ZRINIT, so shorter repeats livelock it.
  const bool cut = args.cut_after != UINT64_MAX;
  bool ok = true;
  for (int session = 0; session < (cut ? 2 : 1); ++session) {
    const bool cut_now = cut && session == 0;
    std::vector<std::string> command;
    if (to_rz) {
      command = {"rz", "-b", "-vv"};
      if (session > 0) command.emplace_back("-r");  // crash recovery: resume what the first session left
      if (args.escape) command.emplace_back("-e");
    } else {
      command = {"sz", "-b", "-vv"};
      if (args.escape) command.emplace_back("-e");
      command.insert(command.end(), names.begin(), names.end());
    }
    Peer peer = spawn(command, to_rz ? to_dir : from_dir);
    if (peer.pid < 0) return 1;
    RelayStream relay(peer.master, args.corruption, args.seed + 1000 + static_cast<std::uint64_t>(session),
                      cut_now ? args.cut_after : UINT64_MAX, args.fin_xoff, args.fin_lose);
    SessionResult result;
    PosixFileAccess posix_files(to_rz ? from_dir.string() : to_dir.string());
    TimedFiles files(posix_files);
    if (to_rz) {
      Sender sender(relay, files, options);
      for (const auto& n : names) sender.add_file(n);
      result = run_session(sender, peer, relay, args.limit_s, cut_now);
    } else {
      Receiver receiver(relay, files, options);
      result = run_session(receiver, peer, relay, args.limit_s, cut_now);
    }
    print(cut_now ? "session 1 (carrier lost)" : "session", result, payload, relay);
    std::printf("  longest file-store call %lld us\n", static_cast<long long>(files.longest_us));
    if (cut_now) {
      // No truncated file may appear under a real name on the glider side.
      if (!to_rz) {
        for (const auto& n : names) {
          if (fs::exists(to_dir / n) && read_file(to_dir / n) != read_file(from_dir / n)) {
            std::printf("FAIL: %s visible with wrong content after the carrier loss\n", n.c_str());
            ok = false;
          }
        }
      }
      continue;
    }
    if (cut && result.link_bytes + args.cut_after / 2 > payload) {
      // A resume sends the rest only: far less than the whole payload again.
      std::printf("FAIL: the second session moved %llu bytes of %llu: no resume\n",
                  static_cast<unsigned long long>(result.link_bytes), static_cast<unsigned long long>(payload));
      ok = false;
    }
    if (cut) std::printf("  second session: %llu link bytes\n", static_cast<unsigned long long>(result.link_bytes));
    if (result.status != Status::done) {
      std::printf("FAIL: engine ended %s\n", failure_name(result.failure));
      ok = false;
    }
    if (result.peer_exit != 0) {
      std::printf("FAIL: %s exit %d\n", to_rz ? "rz" : "sz", result.peer_exit);
      ok = false;
    }
  }
  for (const auto& n : names) {
    if (!fs::exists(to_dir / n) || read_file(to_dir / n) != read_file(from_dir / n)) {
      std::printf("FAIL: %s missing or different\n", n.c_str());
      ok = false;
    }
  }
  std::size_t extra = 0;
  for (const auto& entry : fs::directory_iterator(to_dir)) {
    if (std::find(names.begin(), names.end(), entry.path().filename().string()) == names.end()) {
      std::printf("FAIL: leftover %s\n", entry.path().filename().c_str());
      ++extra;
    }
  }
  ok = ok && extra == 0;
  if (ok) fs::remove_all(root);
  if (ok) {
    std::printf("PASS\n");
  } else {
    std::printf("FAIL (files kept in %s)\n", root.c_str());
  }
  return ok ? 0 : 1;
}
