// SPDX-License-Identifier: Apache-2.0
#include "glider/netcdf/og1_reader.hpp"

#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "glider/netcdf/nc_file.hpp"

namespace glider::netcdf {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;

struct Mapping {
  const char* og1;
  const char* contract;
  double scale;  // contract = og1 x scale
};
const Mapping kMappings[] = {
    {"TIME", "m_present_time", 1.0},
    {"DEPTH", "m_depth", 1.0},
    {"PITCH", "m_pitch", kRadPerDeg},
    {"ROLL", "m_roll", kRadPerDeg},
    {"HEADING", "m_heading", kRadPerDeg},
    {"PRES", "sci_water_pressure", 0.1},
    {"TEMP", "sci_water_temp", 1.0},
    {"CNDC", "sci_water_cond", 0.1},
    {"PUMPED_VOLUME", "m_ballast_pumped", 1.0},
};

// The values of a numeric 1-D variable, fill (and the library's default fill,
// and anything not finite) as NaN.
std::vector<double> read_values(const NcFile& f, int var, std::size_t n) {
  std::vector<double> values(n);
  if (n) f.check(nc_get_var_double(f.id(), var, values.data()), "get_var_double");
  // The _FillValue attribute marks the missing values whatever the file's
  // fill mode (the writers here create files in NC_NOFILL mode, for which
  // nc_inq_var_fill says "no fill" although every missing value is the fill).
  double fill = kNaN;
  nc_type type = 0;
  size_t length = 0;
  if (nc_inq_att(f.id(), var, "_FillValue", &type, &length) == NC_NOERR && length == 1) {
    f.check(nc_get_att_double(f.id(), var, "_FillValue", &fill), "get_att_double _FillValue");
  }
  for (double& v : values) {
    if (!std::isfinite(v) || v == fill || (std::isfinite(fill) && std::abs(v - fill) <= 1e-6 * std::abs(fill))) {
      v = kNaN;  // the float fill read as double (-9999.9f) is not exactly the double -9999.9
    }
  }
  return values;
}

}  // namespace

bool is_netcdf_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  in.read(magic, 4);
  return in.gcount() == 4 && ((magic[0] == 'C' && magic[1] == 'D' && magic[2] == 'F') ||
                              (magic[0] == '\x89' && magic[1] == 'H' && magic[2] == 'D' && magic[3] == 'F'));
}

flightlog::FlightLog read_og1_log(const std::filesystem::path& path, const flightlog::ReadOptions& options) {
  NcFile f = NcFile::open(path);
  const std::string source = path.string();
  int dim = -1;
  if (nc_inq_dimid(f.id(), "N_MEASUREMENTS", &dim) != NC_NOERR) {
    throw flightlog::FlightLogError(source, 0, "", 0, "not an OG1.0 file: no N_MEASUREMENTS dimension");
  }
  size_t n = 0;
  f.check(nc_inq_dimlen(f.id(), dim, &n), "inq_dimlen");
  int nvars = 0;
  f.check(nc_inq_nvars(f.id(), &nvars), "inq_nvars");
  std::vector<std::string> names;
  std::vector<flightlog::Column> columns;
  for (int var = 0; var < nvars; ++var) {
    char name[NC_MAX_NAME + 1];
    nc_type type = 0;
    int ndims = 0;
    int dims[NC_MAX_VAR_DIMS];
    f.check(nc_inq_var(f.id(), var, name, &type, &ndims, dims, nullptr), "inq_var");
    const bool numeric = type == NC_BYTE || type == NC_SHORT || type == NC_INT || type == NC_FLOAT ||
                         type == NC_DOUBLE || type == NC_UBYTE || type == NC_USHORT || type == NC_UINT ||
                         type == NC_INT64 || type == NC_UINT64;
    if (!numeric || ndims != 1 || dims[0] != dim) continue;
    std::string column = name;
    std::vector<double> values = read_values(f, var, n);
    for (const Mapping& m : kMappings) {
      if (column != m.og1) continue;
      column = m.contract;
      for (double& v : values) v *= m.scale;
    }
    for (const auto& [from, to] : options.rename) {
      if (column == from) column = to;
    }
    if (!options.columns.empty() && column != options.time_column &&
        std::find(options.columns.begin(), options.columns.end(), column) == options.columns.end()) {
      bool required = false;
      for (const auto& alternatives : options.required) {
        required = required || std::find(alternatives.begin(), alternatives.end(), column) != alternatives.end();
      }
      if (!required) continue;
    }
    if (std::find(names.begin(), names.end(), column) != names.end()) {
      throw flightlog::FlightLogError(source, 0, column, 0, "two variables read as this column");
    }
    names.push_back(column);
    columns.push_back(std::move(values));
  }
  const auto time = std::find(names.begin(), names.end(), options.time_column);
  if (time == names.end()) {
    throw flightlog::FlightLogError(source, 0, options.time_column, 0, "time column missing (OG1.0: TIME)");
  }
  const auto time_index = static_cast<std::size_t>(time - names.begin());
  const flightlog::Column& t = columns[time_index];
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i]) || (i > 0 && !(t[i] > t[i - 1]))) {
      throw flightlog::FlightLogError(source, i + 1, options.time_column, time_index + 1,
                                      "time empty or not increasing at measurement " + std::to_string(i + 1));
    }
  }
  if (t.empty()) throw flightlog::FlightLogError(source, 0, "", 0, "no measurements");
  for (const auto& alternatives : options.required) {
    if (alternatives.empty() || std::any_of(alternatives.begin(), alternatives.end(), [&](const std::string& a) {
          return std::find(names.begin(), names.end(), a) != names.end();
        })) {
      continue;
    }
    std::string problem = "required column missing from the OG1.0 file";
    for (std::size_t i = 1; i < alternatives.size(); ++i) problem += (i == 1 ? " (nor " : ", ") + alternatives[i];
    if (alternatives.size() > 1) problem += ")";
    problem += "; give another variable with --rename NAME=" + alternatives.front();
    throw flightlog::FlightLogError(source, 0, alternatives.front(), 0, problem);
  }
  return flightlog::FlightLog(source, {{"source", "OG1.0 file " + source}}, std::move(names), std::move(columns),
                              time_index);
}

}  // namespace glider::netcdf
