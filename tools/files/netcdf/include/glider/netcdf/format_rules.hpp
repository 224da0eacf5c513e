// SPDX-License-Identifier: Apache-2.0
#pragma once
// The required elements of OG1.0 and IOOS NGDAC v2, written down from their
// specifications as ONE table (format_rules.cpp), one row per rule with its
// source. The checker (checker.hpp) applies it to any file; docs/netcdf.md
// prints it (glider-check-nc --rules).
#include <span>
#include <string_view>

namespace glider::netcdf {

enum class Format { kOg1, kIoos };
std::string_view to_string(Format format);

enum class RuleKind {
  kGlobalAttribute,  // attribute present (and, with `expected`, equal; "~x": contains x; "@compact": YYYYmmddTHHMMSS)
  kGlobalText,       // every global attribute is a string
  kDimension,        // dimension present; expected "unlimited": unlimited
  kVariable,         // variable present with type and dimensions `expected` ("double(N_MEASUREMENTS)", "int()")
  kAttributes,       // the variable has every attribute listed (space separated)
  kAttributeValue,   // variable:attribute equals `expected`
  kNoFillValue,      // a coordinate variable has no _FillValue (CF)
  kValidRange,       // every value that is not the fill lies in [valid_min, valid_max] of the variable
  kParams,   // every <PARAM> (a variable with a vocabulary attribute, or an OG1 parameter name) has the attributes
  kSensors,  // at least one SENSOR_* variable, each with the attributes listed
  kSensorReferences,  // every `sensor` attribute names a variable of the file
  kAncillary,         // every ancillary_variables attribute names variables of the file
  kVocabulary,        // the variable's value (or flag values) is a term of the vocabulary `expected`
};

struct Rule {
  Format format;
  const char* id;
  RuleKind kind;
  const char* variable;   // "" for global rules
  const char* attribute;  // attribute name(s)
  const char* expected;
  const char* requirement;  // "mandatory", "highly desirable", "required" (IOOS)
  const char* source;       // specification, section
};

std::span<const Rule> format_rules();

}  // namespace glider::netcdf
