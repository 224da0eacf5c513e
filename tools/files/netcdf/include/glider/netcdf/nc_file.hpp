// SPDX-License-Identifier: Apache-2.0
#pragma once
// A thin RAII layer over the NetCDF C library (Debian's libnetcdf-dev): every
// byte of the files is written and read by the library itself; this only
// turns its status codes into exceptions that name the file and the call.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "glider/netcdf/dataset_sink.hpp"

namespace glider::netcdf {

class NcError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One open NetCDF file. Writing: create() (NetCDF-4, as OG1.0 requires, or
// classic for IOOS), define, end_define(), put. Reading: open().
class NcFile final : public DatasetSink {
 public:
  enum class Kind { kNetcdf4, kClassic };
  static NcFile create(const std::filesystem::path& path, Kind kind);
  static NcFile open(const std::filesystem::path& path);
  NcFile(NcFile&& other) noexcept;
  NcFile& operator=(NcFile&&) = delete;
  NcFile(const NcFile&) = delete;
  ~NcFile() override;
  void close();  // throws on a write error; the destructor only closes

  int id() const { return id_; }
  const std::string& path() const { return path_; }

  // Definition mode.
  int def_dim(const std::string& name, std::size_t length) override;  // 0 = unlimited
  int def_var(const std::string& name, int nc_type, const std::vector<int>& dims) override;
  void set_chunking(int var, std::size_t chunk) override;
  void put_att(int var, const std::string& name, std::string_view text) override;  // var -1: global
  void put_att(int var, const std::string& name, double value) override;
  void put_att(int var, const std::string& name, int nc_type, const std::vector<double>& values) override;
  void end_define() override;

  // Data mode.
  void put(int var, const std::vector<double>& values) override;  // converted to the variable's type by the library
  void put(int var, const std::vector<std::int8_t>& values) override;   // byte
  void put(int var, const std::vector<std::int32_t>& values) override;  // int
  void put_scalar(int var, double value) override;
  void put_scalar_int(int var, int value) override;
  void put_string(int var, const std::string& value) override;  // NC_STRING scalar
  void put_chars(int var, const std::string& value);            // NC_CHAR array, padded with NULs

  void check(int status, const std::string& what) const;

 private:
  NcFile(int id, std::string path) : id_(id), path_(std::move(path)) {}
  int id_ = -1;
  std::string path_;
};

}  // namespace glider::netcdf
