// SPDX-License-Identifier: Apache-2.0
#pragma once
// The science computer's sensors on the flight computer's time: each
// sensor's samples from all science files in order (time
// sci_m_present_time), bad CTD records removed, linearly interpolated onto
// the flight rows only between samples less than max_gap_s apart.
#include <map>
#include <string>
#include <vector>

#include "glider/flightlog/flight_log.hpp"
#include "glider/slocum/binary_file.hpp"

namespace glider::slocum::detail {

class ScienceTrack {
 public:
  ScienceTrack(const std::vector<BinaryFile>& files, double max_gap_s);
  // NaN where no bracketing pair is close enough; non-finite samples are
  // skipped and counted in non_finite[name].
  flightlog::Column interpolate(const std::string& name, const std::vector<double>& time,
                                std::map<std::string, std::size_t>& non_finite) const;

 private:
  const std::vector<BinaryFile>& files_;
  double max_gap_s_;
  // Per file, per cycle: a CTD record to drop (timestamp <= 0, or P=T=C=0).
  std::vector<std::vector<bool>> bad_ctd_;
};

}  // namespace glider::slocum::detail
