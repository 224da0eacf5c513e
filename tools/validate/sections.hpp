#pragma once
#include <filesystem>

#include "glider/report/report.hpp"

namespace glider::validate {
using report::Report;
using report::fixed;

struct Inputs {
  std::filesystem::path boards;      // boards/vehicles
  std::filesystem::path papers;      // tests/data/papers
  std::filesystem::path real_data;   // tests/data/real
};

void paper000(Report& report, const Inputs& in);
void paper001(Report& report, const Inputs& in);
void paper002(Report& report, const Inputs& in);
void real_data(Report& report, const Inputs& in);
// Paper 000 sec. 3 (glider_identification) on the tables of papers 000 and 001.
void steady_identification_section(Report& report, const Inputs& in);

}  // namespace glider::validate
