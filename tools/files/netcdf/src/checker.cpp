// SPDX-License-Identifier: Apache-2.0
#include "glider/netcdf/checker.hpp"

#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "glider/netcdf/deployment_metadata.hpp"
#include "glider/netcdf/nc_file.hpp"

namespace glider::netcdf {
namespace {

std::vector<std::string> words(const char* text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// OG1.0 parameter names ([OG1] Geophysical variables: "a parameter listed in
// the control vocabulary"): the OG1 collection's common glider parameters.
const std::vector<std::string> kOg1Params = {"PRES",   "TEMP", "CNDC",       "PSAL",      "DOXY",      "CHLA",
                                             "BBP700", "CDOM", "MOLAR_DOXY", "TEMP_DOXY", "PHASE_DOXY"};

class Inspector {
 public:
  explicit Inspector(NcFile& file) : f_(file) {}

  int var(const std::string& name) const {
    int id = -1;
    return nc_inq_varid(f_.id(), name.c_str(), &id) == NC_NOERR ? id : -1;
  }
  bool has_att(int var, const std::string& name) const {
    return nc_inq_attid(f_.id(), var, name.c_str(), nullptr) == NC_NOERR;
  }
  // An attribute's text (NC_CHAR or NC_STRING); nullopt if absent or not text.
  std::optional<std::string> text(int var, const std::string& name) const {
    nc_type type = 0;
    size_t length = 0;
    if (nc_inq_att(f_.id(), var, name.c_str(), &type, &length) != NC_NOERR) return std::nullopt;
    if (type == NC_CHAR) {
      std::string s(length, '\0');
      if (length) f_.check(nc_get_att_text(f_.id(), var, name.c_str(), s.data()), "get_att_text " + name);
      while (!s.empty() && s.back() == '\0') s.pop_back();
      return s;
    }
    if (type == NC_STRING && length >= 1) {
      std::vector<char*> values(length);
      f_.check(nc_get_att_string(f_.id(), var, name.c_str(), values.data()), "get_att_string " + name);
      std::string s = values[0] ? values[0] : "";
      nc_free_string(length, values.data());
      return s;
    }
    return std::nullopt;
  }
  std::optional<double> number(int var, const std::string& name) const {
    nc_type type = 0;
    size_t length = 0;
    if (nc_inq_att(f_.id(), var, name.c_str(), &type, &length) != NC_NOERR || type == NC_CHAR || type == NC_STRING ||
        length < 1) {
      return std::nullopt;
    }
    std::vector<double> values(length);
    f_.check(nc_get_att_double(f_.id(), var, name.c_str(), values.data()), "get_att_double " + name);
    return values[0];
  }
  std::string type_and_dims(int var) const {
    nc_type type = 0;
    int ndims = 0;
    int dims[NC_MAX_VAR_DIMS];
    f_.check(nc_inq_var(f_.id(), var, nullptr, &type, &ndims, dims, nullptr), "inq_var");
    const char* names[] = {"",      "byte",   "char", "short", "int",    "float", "double",
                           "ubyte", "ushort", "uint", "int64", "uint64", "string"};
    std::string out = (type >= 1 && type <= 12) ? names[type] : "user";
    out += "(";
    for (int d = 0; d < ndims; ++d) {
      char name[NC_MAX_NAME + 1];
      f_.check(nc_inq_dimname(f_.id(), dims[d], name), "inq_dimname");
      if (d > 0) out += ',';
      out += name;
    }
    return out + ")";
  }
  std::vector<double> values(int var) const {
    int ndims = 0;
    int dims[NC_MAX_VAR_DIMS];
    f_.check(nc_inq_var(f_.id(), var, nullptr, nullptr, &ndims, dims, nullptr), "inq_var");
    size_t n = 1;
    for (int d = 0; d < ndims; ++d) {
      size_t length = 0;
      f_.check(nc_inq_dimlen(f_.id(), dims[d], &length), "inq_dimlen");
      n *= length;
    }
    std::vector<double> out(n);
    if (n) f_.check(nc_get_var_double(f_.id(), var, out.data()), "get_var_double");
    return out;
  }
  std::vector<std::string> variables() const {
    int n = 0;
    f_.check(nc_inq_nvars(f_.id(), &n), "inq_nvars");
    std::vector<std::string> out;
    for (int v = 0; v < n; ++v) {
      char name[NC_MAX_NAME + 1];
      f_.check(nc_inq_varname(f_.id(), v, name), "inq_varname");
      out.emplace_back(name);
    }
    return out;
  }
  // A string variable's (NC_STRING scalar or char array) value.
  std::optional<std::string> string_value(int var) const {
    nc_type type = 0;
    f_.check(nc_inq_vartype(f_.id(), var, &type), "inq_vartype");
    if (type == NC_STRING) {
      char* value = nullptr;
      if (nc_get_var_string(f_.id(), var, &value) != NC_NOERR) return std::nullopt;
      std::string s = value ? value : "";
      nc_free_string(1, &value);
      return s;
    }
    return std::nullopt;
  }
  NcFile& file() const { return f_; }

 private:
  NcFile& f_;
};

bool is_compact_time(const std::string& s) {
  return s.size() == 15 && s[8] == 'T' &&
         std::all_of(s.begin(), s.end(), [](char c) { return (c >= '0' && c <= '9') || c == 'T'; });
}

class Checker {
 public:
  Checker(const Inspector& in, CheckResult& result) : in_(in), r_(result) {}

  void apply(const Rule& rule) {
    ++r_.rules_checked;
    rule_ = &rule;
    switch (rule.kind) {
      case RuleKind::kGlobalAttribute:
        return global_attribute(rule);
      case RuleKind::kGlobalText:
        return global_text();
      case RuleKind::kDimension:
        return dimension(rule);
      case RuleKind::kVariable:
        return for_each_variable(rule, [&](int v, const std::string& name) {
          const std::string got = in_.type_and_dims(v);
          if (got != rule.expected) flag(name + ": is " + got + ", the format asks for " + rule.expected);
        });
      case RuleKind::kAttributes:
        return for_each_variable(rule, [&](int v, const std::string& name) {
          for (const std::string& a : words(rule.attribute)) {
            if (!in_.has_att(v, a)) flag(name + ": no attribute " + a);
          }
        });
      case RuleKind::kAttributeValue:
        return for_each_variable(rule, [&](int v, const std::string& name) {
          const auto value = in_.text(v, rule.attribute);
          if (!value)
            flag(name + ": no text attribute " + rule.attribute);
          else if (*value != rule.expected) {
            flag(name + ":" + rule.attribute + " is '" + *value + "', the format asks for '" + rule.expected + "'");
          }
        });
      case RuleKind::kNoFillValue:
        return for_each_variable(rule, [&](int v, const std::string& name) {
          if (in_.has_att(v, "_FillValue")) flag(name + ": a coordinate variable must not have a _FillValue");
        });
      case RuleKind::kValidRange:
        return for_each_variable(rule, [&](int v, const std::string& name) { valid_range(v, name); });
      case RuleKind::kParams:
        return params(rule);
      case RuleKind::kSensors:
        return sensors(rule);
      case RuleKind::kSensorReferences:
        return sensor_references();
      case RuleKind::kAncillary:
        return ancillary();
      case RuleKind::kVocabulary:
        return vocabulary(rule);
    }
  }

 private:
  void flag(const std::string& message) { r_.findings.push_back({rule_, message}); }

  template <typename Body>
  void for_each_variable(const Rule& rule, Body body) {
    for (const std::string& name : words(rule.variable)) {
      const int v = in_.var(name);
      if (v < 0) {
        flag("no variable " + name);
        continue;
      }
      body(v, name);
    }
  }

  void global_attribute(const Rule& rule) {
    for (const std::string& a : words(rule.attribute)) {
      const auto value = in_.text(NC_GLOBAL, a);
      if (!value) {
        flag(in_.has_att(NC_GLOBAL, a) ? "global attribute " + a + " is not text" : "no global attribute " + a);
        continue;
      }
      const std::string expected = rule.expected;
      if (value->empty())
        flag("global attribute " + a + " is empty");
      else if (expected == "@compact" && !is_compact_time(*value)) {
        flag("global attribute " + a + " is '" + *value + "', not YYYYmmddTHHMMSS");
      } else if (!expected.empty() && expected[0] == '~' && value->find(expected.substr(1)) == std::string::npos) {
        flag("global attribute " + a + " is '" + *value + "', does not contain '" + expected.substr(1) + "'");
      } else if (!expected.empty() && expected[0] != '~' && expected[0] != '@' && *value != expected) {
        flag("global attribute " + a + " is '" + *value + "', the format asks for '" + expected + "'");
      }
    }
  }

  void global_text() {
    int n = 0;
    in_.file().check(nc_inq_natts(in_.file().id(), &n), "inq_natts");
    for (int i = 0; i < n; ++i) {
      char name[NC_MAX_NAME + 1];
      in_.file().check(nc_inq_attname(in_.file().id(), NC_GLOBAL, i, name), "inq_attname");
      if (!in_.text(NC_GLOBAL, name)) flag(std::string("global attribute ") + name + " is not a string");
    }
  }

  void dimension(const Rule& rule) {
    int dim = -1;
    if (nc_inq_dimid(in_.file().id(), rule.variable, &dim) != NC_NOERR) {
      flag(std::string("no dimension ") + rule.variable);
      return;
    }
    if (std::string(rule.expected) == "unlimited") {
      int unlimited[NC_MAX_DIMS];
      int count = 0;
      in_.file().check(nc_inq_unlimdims(in_.file().id(), &count, unlimited), "inq_unlimdims");
      if (std::find(unlimited, unlimited + count, dim) == unlimited + count) {
        flag(std::string("dimension ") + rule.variable + " is not unlimited");
      }
    }
  }

  void valid_range(int v, const std::string& name) {
    const auto lo = in_.number(v, "valid_min"), hi = in_.number(v, "valid_max");
    if (!lo || !hi) {
      flag(name + ": no numeric valid_min/valid_max");
      return;
    }
    const auto fill = in_.number(v, "_FillValue");
    std::size_t bad = 0, first = 0;
    double first_value = 0.0;
    const std::vector<double> values = in_.values(v);
    for (std::size_t i = 0; i < values.size(); ++i) {
      const double x = values[i];
      if ((fill && x == *fill) || std::isnan(x)) continue;
      if (x < *lo || x > *hi) {
        if (bad++ == 0) first = i, first_value = x;
      }
    }
    if (bad) {
      char text[160];
      std::snprintf(text, sizeof text, ": %zu value(s) outside [%g, %g] (first: index %zu, %g)", bad, *lo, *hi, first,
                    first_value);
      flag(name + text);
    }
  }

  bool is_param(const std::string& name) const {
    const int v = in_.var(name);
    if (name.size() > 3 && name.compare(name.size() - 3, 3, "_QC") == 0) return false;
    return in_.has_att(v, "vocabulary") || std::find(kOg1Params.begin(), kOg1Params.end(), name) != kOg1Params.end();
  }

  void params(const Rule& rule) {
    for (const std::string& name : in_.variables()) {
      if (!is_param(name)) continue;
      const int v = in_.var(name);
      for (const std::string& a : words(rule.attribute)) {
        if (!in_.has_att(v, a)) flag(name + ": no attribute " + a);
      }
    }
  }

  void sensors(const Rule& rule) {
    bool any = false;
    for (const std::string& name : in_.variables()) {
      if (name.rfind("SENSOR_", 0) != 0) continue;
      any = true;
      const int v = in_.var(name);
      for (const std::string& a : words(rule.attribute)) {
        if (!in_.has_att(v, a)) flag(name + ": no attribute " + a);
      }
    }
    if (!any) flag("no SENSOR_<sensor_type>_<sensor_serial_number> variable");
  }

  void sensor_references() {
    for (const std::string& name : in_.variables()) {
      const auto sensor = in_.text(in_.var(name), "sensor");
      if (sensor && in_.var(*sensor) < 0) flag(name + ":sensor names '" + *sensor + "', which is not a variable");
    }
  }

  void ancillary() {
    for (const std::string& name : in_.variables()) {
      const auto list = in_.text(in_.var(name), "ancillary_variables");
      if (!list) continue;
      for (const std::string& other : words(list->c_str())) {
        if (in_.var(other) < 0) flag(name + ":ancillary_variables names '" + other + "', which is not a variable");
      }
    }
  }

  void vocabulary(const Rule& rule) {
    const int v = in_.var(rule.variable);
    if (v < 0) {
      if (std::string(rule.requirement) == "mandatory") flag(std::string("no variable ") + rule.variable);
      return;
    }
    if (std::string(rule.expected) == "phase") {
      // [OGV] phase.md: ids 0-7.
      std::size_t bad = 0;
      for (double x : in_.values(v)) bad += !(x >= 0 && x <= 7 && x == std::floor(x));
      if (bad) flag(std::to_string(bad) + " PHASE value(s) outside the phase vocabulary's ids 0-7");
      return;
    }
    const auto value = in_.string_value(v);
    if (!value) {
      flag(std::string(rule.variable) + ": not a string variable");
      return;
    }
    for (const Vocabulary& vocabulary : metadata_vocabularies()) {
      if (rule.expected != std::string(vocabulary.key)) continue;
      for (const std::string& term : vocabulary.terms) {
        if (term == *value) return;
      }
      flag(std::string(rule.variable) + " is '" + *value + "', not a term of " + vocabulary.source);
    }
  }

  const Inspector& in_;
  CheckResult& r_;
  const Rule* rule_ = nullptr;
};

std::optional<Format> declared_format(const Inspector& in) {
  const auto conventions = in.text(NC_GLOBAL, "Conventions");
  if (conventions && conventions->find("OG-1.0") != std::string::npos) return Format::kOg1;
  const auto version = in.text(NC_GLOBAL, "format_version");
  if (version && version->rfind("IOOS_Glider_NetCDF_v2", 0) == 0) return Format::kIoos;
  return std::nullopt;
}

}  // namespace

CheckResult check_file(const std::filesystem::path& path, std::optional<Format> format) {
  NcFile file = NcFile::open(path);
  const Inspector in(file);
  CheckResult result;
  result.format = format ? format : declared_format(in);
  if (!result.format) {
    result.findings.push_back({nullptr,
                               "neither OG1.0 (Conventions containing 'OG-1.0') nor IOOS NGDAC v2 "
                               "(format_version 'IOOS_Glider_NetCDF_v2.0.nc'): give --format"});
    return result;
  }
  Checker checker(in, result);
  for (const Rule& rule : format_rules()) {
    if (rule.format == *result.format) checker.apply(rule);
  }
  return result;
}

}  // namespace glider::netcdf
