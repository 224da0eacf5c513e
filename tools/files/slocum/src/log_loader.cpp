// SPDX-License-Identifier: Apache-2.0
#include "glider/slocum/log_loader.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "glider/slocum/deployment.hpp"
#ifdef GLIDER_LOG_LOADER_NETCDF
#include "glider/netcdf/og1_reader.hpp"
#endif

namespace glider::slocum {
namespace {

constexpr const char* kScienceTime = "sci_m_present_time";

// Science files alone (.ebd/.tbd/.nbd) have only the science computer's clock:
// glider-convert times their log by sci_m_present_time. A tool asking for the
// default time column takes that one; a tool naming another is not changed.
bool takes_science_time(const flightlog::ReadOptions& options, const std::string& time_name) {
  return time_name == kScienceTime && options.time_column == flightlog::ReadOptions{}.time_column;
}

// The CSV glider-convert wrote from science files alone: its header (the
// first line that is not a `#` line) has sci_m_present_time, not m_present_time.
bool csv_of_science_files(const std::string& path) {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line.front() == '#') continue;
    std::istringstream header(line);
    bool science = false;
    for (std::string name; std::getline(header, name, ',');) {
      while (!name.empty() && (name.back() == '\r' || name.back() == ' ')) name.pop_back();
      if (name == flightlog::ReadOptions{}.time_column) return false;
      science = science || name == kScienceTime;
    }
    return science;
  }
  return false;
}

}  // namespace

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
  if (!is_binary_log(source.inputs)) {
    if (takes_science_time(options, kScienceTime) && csv_of_science_files(source.inputs.front())) {
      flightlog::ReadOptions science = options;
      science.time_column = kScienceTime;
      return flightlog::read_flight_log(source.inputs.front(), science);
    }
    return flightlog::read_flight_log(source.inputs.front(), options);
  }

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
  if (time_name != options.time_column && !takes_science_time(options, time_name)) {
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
