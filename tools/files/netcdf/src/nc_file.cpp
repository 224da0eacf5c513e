// SPDX-License-Identifier: Apache-2.0
#include "glider/netcdf/nc_file.hpp"

#include <netcdf.h>

#include <utility>

namespace glider::netcdf {

void NcFile::check(int status, const std::string& what) const {
  if (status != NC_NOERR) throw NcError(path_ + ": NetCDF " + what + ": " + nc_strerror(status));
}

NcFile NcFile::create(const std::filesystem::path& path, Kind kind) {
  int id = -1;
  const int mode = NC_CLOBBER | (kind == Kind::kNetcdf4 ? NC_NETCDF4 : NC_64BIT_OFFSET);
  NcFile file(-1, path.string());
  file.check(nc_create(path.c_str(), mode, &id), "create");
  file.id_ = id;
  // No fill pass: every variable is written whole, so pre-filling would write it twice.
  int old_mode = 0;
  file.check(nc_set_fill(id, NC_NOFILL, &old_mode), "set_fill");
  return file;
}

NcFile NcFile::open(const std::filesystem::path& path) {
  int id = -1;
  NcFile file(-1, path.string());
  file.check(nc_open(path.c_str(), NC_NOWRITE, &id), "open");
  file.id_ = id;
  return file;
}

NcFile::NcFile(NcFile&& other) noexcept : id_(std::exchange(other.id_, -1)), path_(std::move(other.path_)) {}

NcFile::~NcFile() {
  if (id_ >= 0) nc_close(id_);
}

void NcFile::close() {
  const int id = std::exchange(id_, -1);
  if (id >= 0) check(nc_close(id), "close");
}

int NcFile::def_dim(const std::string& name, std::size_t length) {
  int dim = -1;
  check(nc_def_dim(id_, name.c_str(), length == 0 ? NC_UNLIMITED : length, &dim), "def_dim " + name);
  return dim;
}

int NcFile::def_var(const std::string& name, int nc_type, const std::vector<int>& dims) {
  int var = -1;
  check(nc_def_var(id_, name.c_str(), nc_type, static_cast<int>(dims.size()), dims.data(), &var), "def_var " + name);
  return var;
}

void NcFile::set_chunking(int var, std::size_t chunk) {
  const size_t sizes[1] = {chunk};
  check(nc_def_var_chunking(id_, var, NC_CHUNKED, sizes), "def_var_chunking");
}

void NcFile::put_att(int var, const std::string& name, std::string_view text) {
  check(nc_put_att_text(id_, var < 0 ? NC_GLOBAL : var, name.c_str(), text.size(), text.data()), "put_att " + name);
}

void NcFile::put_att(int var, const std::string& name, double value) {
  put_att(var, name, NC_DOUBLE, std::vector<double>{value});
}

void NcFile::put_att(int var, const std::string& name, int nc_type, const std::vector<double>& values) {
  const int target = var < 0 ? NC_GLOBAL : var;
  check(nc_put_att_double(id_, target, name.c_str(), nc_type, values.size(), values.data()), "put_att " + name);
}

void NcFile::end_define() { check(nc_enddef(id_), "enddef"); }

void NcFile::put(int var, const std::vector<double>& values) {
  const size_t start[1] = {0};
  const size_t count[1] = {values.size()};
  if (!values.empty()) check(nc_put_vara_double(id_, var, start, count, values.data()), "put_vara_double");
}

void NcFile::put(int var, const std::vector<std::int8_t>& values) {
  const size_t start[1] = {0};
  const size_t count[1] = {values.size()};
  if (!values.empty()) check(nc_put_vara_schar(id_, var, start, count, values.data()), "put_vara_schar");
}

void NcFile::put(int var, const std::vector<std::int32_t>& values) {
  const size_t start[1] = {0};
  const size_t count[1] = {values.size()};
  if (!values.empty()) check(nc_put_vara_int(id_, var, start, count, values.data()), "put_vara_int");
}

void NcFile::put_scalar(int var, double value) { check(nc_put_var_double(id_, var, &value), "put_var_double"); }

void NcFile::put_scalar_int(int var, int value) { check(nc_put_var_int(id_, var, &value), "put_var_int"); }

void NcFile::put_string(int var, const std::string& value) {
  const char* text = value.c_str();
  check(nc_put_var_string(id_, var, &text), "put_var_string");
}

void NcFile::put_chars(int var, const std::string& value) {
  int dim = -1;
  check(nc_inq_vardimid(id_, var, &dim), "inq_vardimid");
  size_t length = 0;
  check(nc_inq_dimlen(id_, dim, &length), "inq_dimlen");
  std::string padded = value.substr(0, length);
  padded.resize(length, '\0');
  check(nc_put_var_text(id_, var, padded.data()), "put_var_text");
}

}  // namespace glider::netcdf
