// SPDX-License-Identifier: Apache-2.0
#pragma once
// One call from a glider, start to hang-up (docs/comms.md, "Shore station"):
// read the surface dialog, identify the glider (whoru -> Vehicle Name:), then
// at the GliderDOS prompt type the pilot's queued commands, send the queued
// to-glider/ files (zr on the glider, sz here), fetch the new data files
// (send PATTERNS on the glider, rz here), publish and convert them, and
// write the journal and one surfacing event.
#include <atomic>
#include <string>

#include "after_surfacing_queue.hpp"
#include "shore_config.hpp"

namespace glider::shore {

// Serves the call on the connected socket `fd` (closed at the end). `stop`
// ends it early (shore shutting down). The glider's health and forecast are
// queued on `after` once the event is written. Never throws.
void serve_call(int fd, const std::string& peer, const ShoreConfig& config, const std::atomic<bool>& stop,
                AfterSurfacingQueue& after);

}  // namespace glider::shore
