// SPDX-License-Identifier: Apache-2.0
#include "glider/model/ctd_profile.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

#include "glider/model/seawater.hpp"

namespace glider::model {

WaterColumn water_column_from_ctd(const std::vector<CtdSample>& samples, double bin_m) {
  struct Sum {
    double depth = 0.0, density = 0.0, temperature = 0.0;
    int n = 0;
  };
  std::map<long, Sum> bins;
  for (const CtdSample& s : samples) {
    const double rho = seawater::density_from_ctd(s.conductivity_s_m, s.temperature_c, s.pressure_dbar);
    if (!std::isfinite(rho) || !std::isfinite(s.depth_m)) continue;
    Sum& bin = bins[std::lround(std::floor(s.depth_m / bin_m))];
    bin.depth += s.depth_m;
    bin.density += rho;
    bin.temperature += s.temperature_c;
    ++bin.n;
  }
  std::vector<ProfileNode> nodes;
  for (const auto& [index, bin] : bins) {
    ProfileNode node;
    node.depth_m = bin.depth / bin.n;
    node.water.density_kg_m3 = bin.density / bin.n;
    node.water.temperature_c = bin.temperature / bin.n;
    if (!nodes.empty() && !(node.depth_m > nodes.back().depth_m)) continue;
    nodes.push_back(node);
  }
  if (nodes.empty()) throw std::invalid_argument("no valid CTD sample for a water column");
  return WaterColumn(std::move(nodes), Oscillation{});
}

}  // namespace glider::model
