// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/launch_time.hpp"

#include "glider/utc_time.hpp"

namespace glider::sil {

bool parse_launch_utc(const std::string& text, std::int64_t& utc_s, std::string& why) {
  const utc::Parsed parsed = utc::parse_iso(text, utc::Rules{2000, 2099, 0});
  if (!parsed.ok) {
    why = std::string("is not a UTC time YYYY-MM-DDTHH:MM:SSZ with a year in [2000, 2099] (") + parsed.problem + ")";
    return false;
  }
  utc_s = parsed.whole_s;
  why.clear();
  return true;
}

}  // namespace glider::sil
