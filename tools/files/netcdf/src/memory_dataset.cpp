// SPDX-License-Identifier: Apache-2.0
#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "glider/netcdf/dataset_sink.hpp"

namespace glider::netcdf {
namespace {

// A value as a variable or attribute of this NetCDF type holds it: floats are
// rounded to float, integers truncated toward zero as the library's C casts do.
double as_type(int nc_type, double value) {
  switch (nc_type) {
    case NC_FLOAT:
      return static_cast<double>(static_cast<float>(value));
    case NC_DOUBLE:
      return value;
    default:
      return std::isfinite(value) ? std::trunc(value) : value;
  }
}

std::vector<double> as_type(int nc_type, std::vector<double> values) {
  for (double& v : values) v = as_type(nc_type, v);
  return values;
}

void set(std::vector<MemoryAttribute>& attributes, MemoryAttribute attribute) {
  for (auto& a : attributes) {
    if (a.name == attribute.name) {
      a = std::move(attribute);  // as nc_put_att: the last value wins
      return;
    }
  }
  attributes.push_back(std::move(attribute));
}

}  // namespace

int MemoryDataset::def_dim(const std::string& name, std::size_t length) {
  dimensions.push_back({name, length, length == 0});
  return static_cast<int>(dimensions.size()) - 1;
}

int MemoryDataset::def_var(const std::string& name, int nc_type, const std::vector<int>& dims) {
  for (const int d : dims) {
    if (d < 0 || static_cast<std::size_t>(d) >= dimensions.size()) throw std::out_of_range("def_var " + name + ": dim");
  }
  variables.push_back({name, nc_type, dims, {}, {}, {}});
  return static_cast<int>(variables.size()) - 1;
}

MemoryVariable& MemoryDataset::variable(int var) {
  if (var < 0 || static_cast<std::size_t>(var) >= variables.size())
    throw std::out_of_range("no variable " + std::to_string(var));
  return variables[static_cast<std::size_t>(var)];
}

void MemoryDataset::put_att(int var, const std::string& name, std::string_view text) {
  set(attributes(var), {name, NC_CHAR, std::string(text), {}});
}

void MemoryDataset::put_att(int var, const std::string& name, double value) {
  put_att(var, name, NC_DOUBLE, std::vector<double>{value});
}

void MemoryDataset::put_att(int var, const std::string& name, int nc_type, const std::vector<double>& values) {
  set(attributes(var), {name, nc_type, {}, as_type(nc_type, values)});
}

void MemoryDataset::put_values(int var, std::vector<double> values) {
  MemoryVariable& v = variable(var);
  // One-dimensional on a record dimension (what the writers write): its length is the data's.
  if (v.dims.size() == 1 && dimensions[static_cast<std::size_t>(v.dims[0])].unlimited) {
    auto& length = dimensions[static_cast<std::size_t>(v.dims[0])].length;
    length = std::max(length, values.size());
  }
  v.values = as_type(v.nc_type, std::move(values));
}

void MemoryDataset::put(int var, const std::vector<double>& values) { put_values(var, values); }

void MemoryDataset::put(int var, const std::vector<std::int8_t>& values) {
  put_values(var, std::vector<double>(values.begin(), values.end()));
}

void MemoryDataset::put(int var, const std::vector<std::int32_t>& values) {
  put_values(var, std::vector<double>(values.begin(), values.end()));
}

void MemoryDataset::put_scalar(int var, double value) { put_values(var, {value}); }

void MemoryDataset::put_scalar_int(int var, int value) { put_values(var, {static_cast<double>(value)}); }

void MemoryDataset::put_string(int var, const std::string& value) { variable(var).text = value; }

}  // namespace glider::netcdf
