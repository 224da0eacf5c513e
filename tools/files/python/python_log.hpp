// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Python module's Log (glider.read_log): the flight log with the reader's
// warnings, shared by the module's source files.
#include <pybind11/numpy.h>

#include <algorithm>
#include <string>
#include <vector>

#include "glider/flightlog/flight_log.hpp"

namespace glider::python {

struct Log {
  flightlog::FlightLog log;
  std::vector<std::string> warnings;
  std::string first_input;  // the first file or folder read: its name may name the glider
};

inline pybind11::array_t<double> to_array(const std::vector<double>& values) {
  pybind11::array_t<double> out(static_cast<pybind11::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

}  // namespace glider::python
