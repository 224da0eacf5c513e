// SPDX-License-Identifier: Apache-2.0
#pragma once
// Control-F at the surface: the mission's files are read again through the
// one mission setup (the same validation as at launch: file:line, key,
// value, range). Only a mission that passes replaces the flown plan (its
// waypoints and surfacing; the yo and the abort limits stay those of the
// launch); a refused one leaves the vehicle flying the old plan and the
// reason goes into the next dialog. Parsing allocates: the parser's memory
// comes from the reload arena reserved at start-up, not the heap
// (reload_arena.hpp); this runs only in the cycle the pilot presses
// Control-F, or when an upload is complete (docs/comms.md).
#include <cstddef>
#include <filesystem>

#include "glider/firmware/app/mission_setup.hpp"
#include "glider/firmware/app/vehicle_setup.hpp"
#include "glider/firmware/comms/comms_task.hpp"

namespace glider::fw::app {

// The reload arena a program reserves at start-up for MissionFileReloader
// (reload_arena.hpp). box_current: a re-read reaches 56 kB of it, an
// upload's install 105 kB (comms.ReloadHeap prints them); 2 MiB leaves room
// for missions some 20 times larger.
constexpr std::size_t kReloadArenaBytes = std::size_t{2} << 20;

class MissionFileReloader final : public comms::MissionReloader {
 public:
  MissionFileReloader(std::filesystem::path mission, VehicleSetup setup, MissionOptions options)
      : mission_(std::move(mission)), setup_(std::move(setup)), options_(options) {}
  bool reread(FlightSoftware& flight, char* refusal, std::size_t size) override;
  // An uploaded .ma (or the flown .mi) is tried on a staged copy of the
  // mission's files beside the received one (<its folder>/.staging); only a
  // plan that passes is flown, and only then does the file replace its
  // namesake among the mission's files (temporary name, then rename).
  bool install(FlightSoftware& flight, const char* received_path, char* refusal, std::size_t size) override;

 private:
  std::filesystem::path mission_;
  VehicleSetup setup_;
  MissionOptions options_;
};

}  // namespace glider::fw::app
