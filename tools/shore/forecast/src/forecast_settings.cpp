// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/forecast_settings.hpp"

#include <toml++/toml.h>

#include <stdexcept>
#include <string>

namespace glider::forecast {
namespace fs = std::filesystem;

TidalPrior current_prior(const fs::path& glider_dir, const PriorOverrides& overrides) {
  TidalPrior prior;
  const fs::path file = glider_dir / "forecast.toml";
  if (fs::is_regular_file(file)) {
    toml::table table;
    try {
      table = toml::parse_file(file.string());
    } catch (const toml::parse_error& e) {
      throw std::runtime_error(file.string() + ":" + std::to_string(e.source().begin.line) + ": " +
                               std::string(e.description()));
    }
    for (const auto& [key, node] : table) {
      if (key.str() != "current_prior" || !node.is_table()) {
        throw std::runtime_error(file.string() + ":" + std::to_string(node.source().begin.line) + ": key '" +
                                 std::string(key.str()) + "' is not a forecast setting (allowed: [current_prior])");
      }
    }
    if (const toml::table* section = table["current_prior"].as_table()) {
      for (const auto& [key, node] : *section) {
        const std::string where = file.string() + ":" + std::to_string(node.source().begin.line) + ": current_prior." +
                                  std::string(key.str());
        if (key.str() == "mode") {
          const std::optional<std::string> text = node.value<std::string>();
          try {
            if (!text) throw std::invalid_argument("not a text (evidence, fixed or off)");
            prior.mode = parse_prior_mode(*text);
          } catch (const std::invalid_argument& e) {
            throw std::runtime_error(where + ": " + e.what());
          }
          continue;
        }
        double* target = key.str() == "mean_sigma_m_s"       ? &prior.mean_sigma_m_s
                         : key.str() == "m2_sigma_m_s"       ? &prior.m2_sigma_m_s
                         : key.str() == "estimate_sigma_m_s" ? &prior.estimate_sigma_m_s
                         : key.str() == "position_sigma_m"   ? &prior.position_sigma_m
                                                             : nullptr;
        if (target == nullptr) {
          throw std::runtime_error(where +
                                   ": unknown key (allowed: mode, mean_sigma_m_s, m2_sigma_m_s, "
                                   "estimate_sigma_m_s, position_sigma_m)");
        }
        const std::optional<double> value = node.value<double>();
        if (!value) throw std::runtime_error(where + ": not a number");
        *target = *value;
        TidalPrior one;  // this key alone against its range
        one.mean_sigma_m_s = key.str() == "mean_sigma_m_s" ? *value : one.mean_sigma_m_s;
        one.m2_sigma_m_s = key.str() == "m2_sigma_m_s" ? *value : one.m2_sigma_m_s;
        one.estimate_sigma_m_s = key.str() == "estimate_sigma_m_s" ? *value : one.estimate_sigma_m_s;
        one.position_sigma_m = key.str() == "position_sigma_m" ? *value : one.position_sigma_m;
        try {
          check_prior(one);
        } catch (const std::invalid_argument& e) {
          throw std::runtime_error(file.string() + ":" + std::to_string(node.source().begin.line) + ": current_prior." +
                                   e.what());
        }
      }
    }
  }
  if (overrides.mode) prior.mode = *overrides.mode;
  if (overrides.mean_sigma_m_s) prior.mean_sigma_m_s = *overrides.mean_sigma_m_s;
  if (overrides.m2_sigma_m_s) prior.m2_sigma_m_s = *overrides.m2_sigma_m_s;
  if (overrides.estimate_sigma_m_s) prior.estimate_sigma_m_s = *overrides.estimate_sigma_m_s;
  if (overrides.position_sigma_m) prior.position_sigma_m = *overrides.position_sigma_m;
  try {
    check_prior(prior);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(std::string("the current prior: ") + e.what());
  }
  return prior;
}

}  // namespace glider::forecast
