// SPDX-License-Identifier: Apache-2.0
#pragma once
// The simulated UTC at launch (glider-sil --launch-utc): SIL's clock starts
// at 0, a glider's at its launch; the Slocum files' names and the dialog's
// Curr Time count from this.
#include <cstdint>
#include <string>

namespace glider::sil {

// `YYYY-MM-DDTHH:MM:SSZ`, years 2000..2099, a real calendar date and time.
// True with `utc_s` (seconds since 1970); false with `why` saying what is
// allowed.
bool parse_launch_utc(const std::string& text, std::int64_t& utc_s, std::string& why);

}  // namespace glider::sil
