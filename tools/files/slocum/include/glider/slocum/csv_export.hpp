// SPDX-License-Identifier: Apache-2.0
#pragma once
// Writes a deployment as the project's flight-log CSV (docs/flight-log.md),
// with the number format of the real-data CSVs in tests/data/real: time to
// 10 us (%.5f), 8-byte values to 12 significant digits (%.12g), 1/2/4-byte
// values to 7 (%.7g: what a float32 holds); empty field = no value.
#include <ostream>

#include "glider/slocum/deployment.hpp"

namespace glider::slocum {

void write_csv(const Deployment& deployment, std::ostream& out);

}  // namespace glider::slocum
