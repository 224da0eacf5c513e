// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <filesystem>

#include "glider/model/vehicle.hpp"
#include "glider/report/report.hpp"

namespace glider::validate {
using report::fixed;
using report::Report;

struct Inputs {
  std::filesystem::path boards;     // boards/vehicles
  std::filesystem::path papers;     // tests/data/papers
  std::filesystem::path real_data;  // tests/data/real
};

// Paper 001 gives the CG position (from the battery through its CAD model),
// not the battery: the battery shift that moves the CG that far from its
// neutral 77 mm, dx_batt = dx_CG M / m_batt.
double stante_battery_pos_m(const model::VehicleParams& vehicle, double xcg_mm);

void paper000(Report& report, const Inputs& in);
void paper001(Report& report, const Inputs& in);
void paper002(Report& report, const Inputs& in);
void real_data(Report& report, const Inputs& in);
// Paper 000 sec. 3 (glider_identification) on the tables of papers 000 and 001.
void steady_identification_section(Report& report, const Inputs& in);

}  // namespace glider::validate
