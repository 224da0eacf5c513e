// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where a writer puts a NetCDF dataset: a file through the NetCDF C library
// (NcFile), or memory (MemoryDataset: the Python module's xarray Dataset is
// built from it). One writer, one variable table: the file and the in-memory
// dataset cannot drift apart.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace glider::netcdf {

class DatasetSink {
 public:
  virtual ~DatasetSink() = default;
  // Definition (var -1: a global attribute; length 0: unlimited).
  virtual int def_dim(const std::string& name, std::size_t length) = 0;
  virtual int def_var(const std::string& name, int nc_type, const std::vector<int>& dims) = 0;
  virtual void set_chunking(int var, std::size_t chunk) = 0;
  virtual void put_att(int var, const std::string& name, std::string_view text) = 0;
  virtual void put_att(int var, const std::string& name, double value) = 0;
  virtual void put_att(int var, const std::string& name, int nc_type, const std::vector<double>& values) = 0;
  virtual void end_define() = 0;
  // Data, converted to the variable's type as the NetCDF library converts it.
  virtual void put(int var, const std::vector<double>& values) = 0;
  virtual void put(int var, const std::vector<std::int8_t>& values) = 0;
  virtual void put(int var, const std::vector<std::int32_t>& values) = 0;
  virtual void put_scalar(int var, double value) = 0;
  virtual void put_scalar_int(int var, int value) = 0;
  virtual void put_string(int var, const std::string& value) = 0;

 protected:
  DatasetSink() = default;
  DatasetSink(const DatasetSink&) = default;
  DatasetSink(DatasetSink&&) = default;
  DatasetSink& operator=(const DatasetSink&) = default;
  DatasetSink& operator=(DatasetSink&&) = default;
};

// A dataset held in memory as the writer defined it: numeric values and
// numeric attributes as doubles already rounded to their NetCDF type (a
// float variable holds exactly the float the file would), strings as text.
struct MemoryAttribute {
  std::string name;
  int nc_type = 0;  // NC_CHAR: text; otherwise values
  std::string text;
  std::vector<double> values;
};

struct MemoryVariable {
  std::string name;
  int nc_type = 0;
  std::vector<int> dims;  // indices into MemoryDataset::dimensions
  std::vector<MemoryAttribute> attributes;
  std::vector<double> values;  // numeric types
  std::string text;            // NC_STRING scalar
};

struct MemoryDimension {
  std::string name;
  std::size_t length = 0;
  bool unlimited = false;
};

class MemoryDataset final : public DatasetSink {
 public:
  int def_dim(const std::string& name, std::size_t length) override;
  int def_var(const std::string& name, int nc_type, const std::vector<int>& dims) override;
  void set_chunking(int /*var*/, std::size_t /*chunk*/) override {}  // storage layout: no meaning in memory
  void put_att(int var, const std::string& name, std::string_view text) override;
  void put_att(int var, const std::string& name, double value) override;
  void put_att(int var, const std::string& name, int nc_type, const std::vector<double>& values) override;
  void end_define() override {}
  void put(int var, const std::vector<double>& values) override;
  void put(int var, const std::vector<std::int8_t>& values) override;
  void put(int var, const std::vector<std::int32_t>& values) override;
  void put_scalar(int var, double value) override;
  void put_scalar_int(int var, int value) override;
  void put_string(int var, const std::string& value) override;

  std::vector<MemoryDimension> dimensions;
  std::vector<MemoryAttribute> globals;
  std::vector<MemoryVariable> variables;

 private:
  MemoryVariable& variable(int var);
  std::vector<MemoryAttribute>& attributes(int var) { return var < 0 ? globals : variable(var).attributes; }
  void put_values(int var, std::vector<double> values);
};

}  // namespace glider::netcdf
