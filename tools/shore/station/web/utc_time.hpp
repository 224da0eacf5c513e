// SPDX-License-Identifier: Apache-2.0
#pragma once
// The console's times: ISO 8601 UTC text <-> unix seconds. NaN = unknown.
#include <limits>
#include <string>

namespace glider::shore::web {

inline constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

// "2026-11-27T05:40:12Z" (fractions of a second allowed); NaN if not that form.
double parse_utc(const std::string& text);
// A call's ID "20261127T054608_0001" -> its start; NaN if not that form.
double parse_call_id(const std::string& id);
// Unix seconds -> "2026-11-27T05:40:12Z"; "" for NaN.
std::string format_utc(double unix_seconds);

}  // namespace glider::shore::web
