// SPDX-License-Identifier: Apache-2.0
#pragma once
// The deployment metadata file (TOML) the user writes once per deployment:
// what the glider's own files cannot say (who, which platform model, which
// CTD, where it was deployed). Keys and vocabularies in docs/netcdf.md. Every
// required key is checked; a missing key, a NaN or a term outside its
// vocabulary is refused with config::ConfigError "file:line[:col]: key: problem".
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace glider::netcdf {

struct DeploymentMetadata {
  std::string source;  // the file read
  // [dataset]
  std::string title, summary, institution, project, license, naming_authority, rtqc_method;
  std::string data_mode;  // "R" (real time) or "delayed": the OG1.0 id's <data_mode>
  // [platform]
  std::string platform_serial, platform_name, platform_model, platform_maker, wmo_id;
  double depth_rating_m = 0.0;
  // [deployment]
  double deployment_time_s = 0.0;  // seconds since 1970 (UTC)
  double deployment_latitude = 0.0, deployment_longitude = 0.0;
  std::string site;
  // [principal_investigator] and [operator]
  std::string pi_name, pi_email, pi_role, operator_institution, operator_role;
  // [ctd]
  std::string ctd_model, ctd_maker, ctd_serial, ctd_calibration_date, ctd_model_vocabulary;
  bool ctd_pumped = true;
};

DeploymentMetadata load_deployment_metadata(const std::filesystem::path& path);
DeploymentMetadata parse_deployment_metadata(std::string_view text, const std::string& source_name);

// The vocabularies the metadata is checked against (terms compared ignoring
// case), with where each comes from.
struct Vocabulary {
  const char* key;     // the metadata key it constrains
  const char* source;  // the vocabulary's document
  std::vector<std::string> terms;
};
const std::vector<Vocabulary>& metadata_vocabularies();

// Seconds since 1970 of "YYYY-MM-DDTHH:MM:SSZ" (or a TOML date-time read
// back as such; glider/utc_time.hpp); NaN if malformed or not a calendar date.
double parse_utc(std::string_view text);
// "YYYYmmddTHHMMSS" (OG1.0) or "YYYY-MM-DDTHH:MM:SSZ" (ISO 8601 extended, IOOS).
std::string format_utc_compact(double seconds);
std::string format_utc_iso(double seconds);

}  // namespace glider::netcdf
