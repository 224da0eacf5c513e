// SPDX-License-Identifier: Apache-2.0
#include "fault_plan.hpp"

#include <stdexcept>

namespace glider::sim_tools {
namespace {

double number_after_colon(const std::string& spec, double min) {
  const auto colon = spec.find(':');
  if (colon == std::string::npos) throw std::invalid_argument("--fault " + spec + ": expected KIND:VALUE");
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(spec.substr(colon + 1), &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != spec.size() - colon - 1 || value < min) {
    throw std::invalid_argument("--fault " + spec + ": bad value");
  }
  return value;
}

}  // namespace

void FaultPlan::add(const std::string& spec) {
  const std::string kind = spec.substr(0, spec.find(':'));
  if (kind == "stall") {
    stall_after_s = number_after_colon(spec, 0.0);
  } else if (kind == "silent") {
    silent_after = static_cast<long>(number_after_colon(spec, 0.0));
  } else if (kind == "noise") {
    garble_every = static_cast<long>(number_after_colon(spec, 1.0));
  } else if (kind == "exception") {
    exception_every = static_cast<long>(number_after_colon(spec, 1.0));
  } else if (kind == "slow") {
    slow_ms = static_cast<int>(number_after_colon(spec, 0.0));
  } else {
    throw std::invalid_argument("--fault " + spec + ": unknown kind (stall, silent, noise, exception, slow)");
  }
}

std::string FaultPlan::describe() const {
  std::string out;
  const auto item = [&](const std::string& text) { out += (out.empty() ? "" : ", ") + text; };
  if (stall_after_s >= 0.0) item("stall after " + std::to_string(stall_after_s) + " s of motion");
  if (silent_after >= 0) item("silent after " + std::to_string(silent_after) + " requests");
  if (garble_every > 0) item("every " + std::to_string(garble_every) + ". reply garbled");
  if (exception_every > 0) item("every " + std::to_string(exception_every) + ". request an exception");
  if (slow_ms > 0) item("replies " + std::to_string(slow_ms) + " ms late");
  return out.empty() ? "none" : out;
}

ReplyAction FaultInjector::next() {
  ++requests_;
  if (plan_.silent_after >= 0 && requests_ > plan_.silent_after) return ReplyAction::kSilent;
  if (plan_.exception_every > 0 && requests_ % plan_.exception_every == 0) return ReplyAction::kException;
  if (plan_.garble_every > 0 && requests_ % plan_.garble_every == 0) return ReplyAction::kGarbled;
  return ReplyAction::kReply;
}

}  // namespace glider::sim_tools
