// SPDX-License-Identifier: Apache-2.0
#include "bench_session.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "glider/firmware/log/log_text.hpp"
#include "glider/hal_linux/register_map.hpp"

namespace glider::bench {
namespace {

namespace regs = hal_linux::regs;
using Clock = std::chrono::steady_clock;

constexpr auto kPollPeriod = std::chrono::milliseconds(100);
constexpr int kMissedAnswersAllowed = 3;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

BenchSession::BenchSession(const hal_linux::ModbusBoard& board, const std::string& csv_path) : board_(board) {
  std::string error;
  link_ = hal_linux::ModbusLink::open(board_.bus, warning_, error);
  if (!link_) throw std::runtime_error(error);
  pump_ = std::make_unique<hal_linux::ModbusAxis>(*link_, board_.pump);
  slide_ = std::make_unique<hal_linux::ModbusAxis>(*link_, board_.slide);
  if (!csv_path.empty()) {
    csv_ = ::open(csv_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (csv_ < 0) throw std::runtime_error(csv_path + ": cannot write: " + std::strerror(errno));
    const std::string header = "# writer: glider-bench\ntime_s,axis,target,position,speed,status,fault_code\n";
    if (!write_whole(header.data(), header.size())) throw std::runtime_error(csv_path + ": cannot write");
  }
}

BenchSession::~BenchSession() {
  if (csv_ < 0) return;
  char trailer[256];
  const std::size_t n = fw::format_log_trailer(outcome_, csv_rows_, csv_lost_, trailer, sizeof trailer);
  write_whole(trailer, n);
  ::close(csv_);
}

// One row, one write(2): the file never holds part of a row (a short write is
// cut back to the last whole row and the row counted as lost).
bool BenchSession::write_whole(const char* data, std::size_t size) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(csv_, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (::ftruncate(csv_, static_cast<off_t>(csv_bytes_)) != 0) return false;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  csv_bytes_ += size;
  return true;
}

hal_linux::ModbusAxis& BenchSession::axis(const std::string& name) { return name == "pump" ? *pump_ : *slide_; }

hal_linux::AxisStatus BenchSession::poll(hal_linux::ModbusAxis& axis) {
  link_->begin_cycle();
  return axis.read_status();
}

MoveOutcome BenchSession::move(hal_linux::ModbusAxis& axis, double target, double rate, bool home) {
  MoveOutcome out;
  const hal_linux::AxisConfig& c = axis.config();
  const hal_linux::AxisStatus before = poll(axis);
  if (!before.answered) {
    out.problem = std::string("no answer: ") + before.error;
    return out;
  }
  link_->begin_cycle();
  if (!(home ? axis.home() : axis.command(target, rate))) {
    out.problem = std::string("command not accepted: ") + link_->last_error();
    return out;
  }
  const double distance = std::abs(target - before.position);
  const double expected_s = distance / std::min(home ? c.max_rate : rate, c.max_rate);
  const double give_up_s = 2.0 * expected_s + 5.0;
  const auto start = Clock::now();
  double last_progress_s = 0.0;
  int missed = 0;
  for (;;) {
    std::this_thread::sleep_for(kPollPeriod);
    const hal_linux::AxisStatus s = poll(axis);
    const double t = seconds_since(start);
    if (!s.answered) {
      if (++missed >= kMissedAnswersAllowed) {
        out.problem = std::string("the device stopped answering: ") + s.error;
        return out;
      }
      continue;
    }
    missed = 0;
    out.samples.push_back({t, s.position, s.speed, s.status_bits, s.fault_code});
    if (csv_ >= 0) {
      char row[256];
      const int n = std::snprintf(row, sizeof row, "%.3f,%s,%g,%g,%g,%u,%u\n", t, c.name.c_str(), target, s.position,
                                  s.speed, static_cast<unsigned>(s.status_bits), static_cast<unsigned>(s.fault_code));
      if (n > 0 && static_cast<std::size_t>(n) < sizeof row && write_whole(row, static_cast<std::size_t>(n))) {
        ++csv_rows_;
      } else {
        ++csv_lost_;
      }
    }
    if (t - last_progress_s >= 1.0) {
      last_progress_s = t;
      const double done = distance > 0.0 ? 100.0 * (1.0 - std::abs(target - s.position) / distance) : 100.0;
      std::fprintf(stderr, "  %-5s %+9.3f %s -> %+9.3f %s  %3.0f%%  %.1f s\n", c.name.c_str(), s.position,
                   c.unit.c_str(), target, c.unit.c_str(), std::max(0.0, done), t);
    }
    if (s.has(regs::kFault)) {
      out.problem = std::string("the actuator reports a fault: ") + regs::fault_name(s.fault_code);
      return out;
    }
    const bool there = home ? s.has(regs::kHomed) && !s.has(regs::kMoving) : s.has(regs::kInPosition);
    if (there) {
      out.arrived = true;
      return out;
    }
    if (t > give_up_s) {
      out.problem = "not in position after " + std::to_string(static_cast<int>(t)) + " s";
      return out;
    }
  }
}

std::string describe_status(const hal_linux::AxisStatus& s, const std::string& unit) {
  char text[160];
  std::snprintf(text, sizeof text, "%+.3f %s, speed %+.3f %s/s", s.position, unit.c_str(), s.speed, unit.c_str());
  std::string out = text;
  const std::pair<std::uint16_t, const char*> bits[] = {
      {regs::kEnabled, "enabled"}, {regs::kMoving, "moving"},      {regs::kInPosition, "in-position"},
      {regs::kHomed, "homed"},     {regs::kLimitMin, "limit-min"}, {regs::kLimitMax, "limit-max"},
      {regs::kFault, "FAULT"}};
  for (const auto& [bit, name] : bits) {
    if (s.has(bit)) out += std::string(", ") + name;
  }
  if (s.has(regs::kFault)) out += std::string(" (") + regs::fault_name(s.fault_code) + ")";
  return out;
}

}  // namespace glider::bench
