// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/comms/parameters.hpp"

#include <cstring>

namespace glider::fw::comms {

bool ParameterTable::add(const char* name, const config::Range& range, double* value) {
  if (count_ >= kMaxParameters || name == nullptr || value == nullptr) return false;
  if (std::strncmp(name, "u_", 2) != 0 || find(name) != nullptr) return false;
  if (!config::within(*value, range)) return false;
  entries_[count_++] = {name, range, value};
  return true;
}

const Parameter* ParameterTable::find(const char* name) const {
  for (std::size_t i = 0; i < count_; ++i) {
    if (std::strcmp(entries_[i].name, name) == 0) return &entries_[i];
  }
  return nullptr;
}

}  // namespace glider::fw::comms
