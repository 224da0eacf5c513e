// SPDX-License-Identifier: Apache-2.0
#include "glider/slocum/log_loader.hpp"

#include <algorithm>

#include "glider/slocum/deployment.hpp"
#ifdef GLIDER_LOG_LOADER_NETCDF
#include "glider/netcdf/og1_reader.hpp"
#endif

namespace glider::slocum {

bool is_binary_log(const std::vector<std::string>& inputs) {
  if (inputs.size() != 1) return true;
  const std::string& input = inputs.front();
  std::error_code error;
  if (std::filesystem::is_directory(input, error)) return true;
  return is_binary_data_name(input) ||
         (!std::filesystem::exists(input, error) && input.find_first_of("*?[") != std::string::npos);
}

flightlog::FlightLog load_flight_log(const LogSource& source, const flightlog::ReadOptions& options,
                                     std::vector<Warning>* warnings) {
  if (source.inputs.empty()) throw std::runtime_error("no flight log given");
#ifdef GLIDER_LOG_LOADER_NETCDF
  if (source.inputs.size() == 1 && netcdf::is_netcdf_file(source.inputs.front())) {
    return netcdf::read_og1_log(source.inputs.front(), options);  // docs/netcdf.md, "Reading OG1.0 back"
  }
#endif
  if (!is_binary_log(source.inputs)) return flightlog::read_flight_log(source.inputs.front(), options);

  DeploymentOptions deployment_options;
  deployment_options.read.cache_dirs = source.cache_dirs;
  deployment_options.rename = options.rename;
  if (!options.columns.empty()) {
    // The columns asked for and every alternative of the required ones; those
    // not in the files are left out here and checked below, as for a CSV.
    deployment_options.columns = options.columns;
    for (const auto& alternatives : options.required) {
      for (const std::string& name : alternatives) deployment_options.columns.push_back(name);
    }
    deployment_options.skip_missing_columns = true;
  }
  Deployment deployment = read_deployment(deployment_files(source.inputs), deployment_options);
  if (warnings != nullptr) warnings->insert(warnings->end(), deployment.warnings.begin(), deployment.warnings.end());
  const flightlog::FlightLog& log = deployment.log;
  const std::string time_name = log.column_names().front();
  if (time_name != options.time_column) {
    throw flightlog::FlightLogError(log.source(), 0, options.time_column, 0,
                                    "time column missing (Slocum binaries have " + time_name + ")");
  }
  for (const auto& alternatives : options.required) {
    if (alternatives.empty() ||
        std::any_of(alternatives.begin(), alternatives.end(), [&log](const std::string& n) { return log.has(n); })) {
      continue;
    }
    std::string problem = "required column missing from the binary files";
    for (std::size_t i = 1; i < alternatives.size(); ++i) problem += (i == 1 ? " (nor " : ", ") + alternatives[i];
    if (alternatives.size() > 1) problem += ")";
    throw flightlog::FlightLogError(log.source(), 0, alternatives.front(), 0, problem);
  }
  return std::move(deployment.log);
}

}  // namespace glider::slocum
