// SPDX-License-Identifier: Apache-2.0
#include "utc_time.hpp"

#include "glider/utc_time.hpp"

namespace glider::shore::web {

double parse_utc(const std::string& text) {
  const utc::Parsed parsed = utc::parse_iso(text);
  return parsed.ok ? parsed.seconds() : kUnknown;
}

double parse_call_id(const std::string& id) {
  // "20261127T054608_0001": the start, then the call's counter.
  const utc::Parsed parsed = utc::parse_compact(std::string_view(id).substr(0, 15));
  return parsed.ok ? parsed.seconds() : kUnknown;
}

std::string format_utc(double unix_seconds) { return utc::format_iso(unix_seconds); }

}  // namespace glider::shore::web
