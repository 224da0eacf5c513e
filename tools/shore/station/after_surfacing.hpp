// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the shore does for a glider after each surfacing event is written
// (docs/health.md, "At the shore"): its flight health from the data that
// came home (ROOT/GLIDER/health/), then (issue 24's forecast) where it will
// surface next. A failure here must never break a call: each step catches
// everything and says what happened in one note, which the session writes
// to the call's journal. The shore runs it off the call's thread, one glider's
// runs in turn (after_surfacing_queue.hpp).
#include <filesystem>
#include <string>
#include <vector>

namespace glider::shore {

// One note per step ("health: ok, 12 segments (1 measured, 0.4 s)", or
// "health: failed: ..."). Never throws.
std::vector<std::string> after_surfacing(const std::filesystem::path& glider_dir) noexcept;

}  // namespace glider::shore
