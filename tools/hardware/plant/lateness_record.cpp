// SPDX-License-Identifier: Apache-2.0
#include "lateness_record.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace glider::plant {

LatenessRecord::LatenessRecord(const std::string& path, double floor_ms) : floor_ms_(floor_ms) {
  if (path.empty()) return;
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) throw std::runtime_error(path + ": cannot write: " + std::strerror(errno));
  std::fputs("kind,t_s,late_ms,requests\n", file_);
  std::fflush(file_);
}

LatenessRecord::~LatenessRecord() {
  if (file_ != nullptr) std::fclose(file_);
}

void LatenessRecord::write(const char* kind, double t_s, double late_ms, int requests) {
  if (file_ == nullptr) return;
  if (late_ms < 0.0) {
    std::fprintf(file_, "%s,%.2f,,%d\n", kind, t_s, requests);
  } else {
    std::fprintf(file_, "%s,%.2f,%.1f,%d\n", kind, t_s, late_ms, requests);
  }
  std::fflush(file_);  // rare rows: each is on disk before the next step
}

void LatenessRecord::step(double t_s, double late_ms) {
  stats_.max_step_late_ms = std::max(stats_.max_step_late_ms, late_ms);
  if (late_ms < floor_ms_) return;
  ++stats_.late_steps;
  write("step", t_s, late_ms, 0);
}

void LatenessRecord::answer(double t_s, double late_ms, int requests) {
  ++stats_.answers;
  stats_.max_requests = std::max<std::uint64_t>(stats_.max_requests, static_cast<std::uint64_t>(requests));
  if (late_ms < 0.0) {
    ++stats_.untimed_answers;
  } else {
    stats_.max_answer_late_ms = std::max(stats_.max_answer_late_ms, late_ms);
  }
  if (late_ms < floor_ms_ && requests <= 1) return;
  ++stats_.late_answers;
  write("answer", t_s, late_ms, requests);
}

std::string LatenessRecord::summary() const {
  char text[256];
  std::snprintf(text, sizeof text,
                "%llu steps >= %.0f ms late (max %.1f ms); %llu Modbus reads, %llu late (>= %.0f ms or several "
                "requests), max answer %.1f ms after its request, at most %llu requests in one read, %llu untimed",
                static_cast<unsigned long long>(stats_.late_steps), floor_ms_, stats_.max_step_late_ms,
                static_cast<unsigned long long>(stats_.answers), static_cast<unsigned long long>(stats_.late_answers),
                floor_ms_, stats_.max_answer_late_ms, static_cast<unsigned long long>(stats_.max_requests),
                static_cast<unsigned long long>(stats_.untimed_answers));
  return text;
}

}  // namespace glider::plant
