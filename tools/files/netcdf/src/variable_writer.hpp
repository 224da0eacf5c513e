// SPDX-License-Identifier: Apache-2.0
#pragma once
// Helpers the two writers share: NaN -> the variable's _FillValue, the QC
// flags of a series, chunking of the record dimension.
#include <cmath>
#include <cstdint>
#include <vector>

#include "glider/netcdf/nc_file.hpp"

namespace glider::netcdf {

inline std::vector<double> with_fill(const std::vector<double>& values, double fill) {
  std::vector<double> out(values);
  for (double& v : out) {
    if (!std::isfinite(v)) v = fill;
  }
  return out;
}

// A value present: `present`; none: `missing`.
inline std::vector<std::int8_t> qc_flags(const std::vector<double>& values, std::int8_t present, std::int8_t missing) {
  std::vector<std::int8_t> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) out[i] = std::isfinite(values[i]) ? present : missing;
  return out;
}

template <typename T>
std::vector<T> slice(const std::vector<T>& values, std::size_t first, std::size_t last) {
  return std::vector<T>(values.begin() + static_cast<long>(first), values.begin() + static_cast<long>(last) + 1);
}

}  // namespace glider::netcdf
