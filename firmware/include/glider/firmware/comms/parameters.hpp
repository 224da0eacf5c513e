// SPDX-License-Identifier: Apache-2.0
#pragma once
// The u_ parameters a pilot may `get` and `put` from the console: a fixed
// table of name, range (the project's config::Range, so a refusal reads as
// everywhere else: key, value, range) and where the value lives. Registered
// at start-up; looked up and written in the loop without allocation.
#include <array>
#include <cstddef>

#include "glider/config/value_limits.hpp"

namespace glider::fw::comms {

struct Parameter {
  const char* name = nullptr;  // u_...
  config::Range range{0.0, 0.0, ""};
  double* value = nullptr;
};

class ParameterTable {
 public:
  static constexpr std::size_t kMaxParameters = 32;

  // Start-up only. False when full, the name is not u_, or the current value is outside its range.
  bool add(const char* name, const config::Range& range, double* value);
  const Parameter* find(const char* name) const;
  std::size_t size() const { return count_; }
  const Parameter& at(std::size_t index) const { return entries_[index]; }

 private:
  std::array<Parameter, kMaxParameters> entries_{};
  std::size_t count_ = 0;
};

}  // namespace glider::fw::comms
