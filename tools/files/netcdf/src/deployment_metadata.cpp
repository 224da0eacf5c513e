// SPDX-License-Identifier: Apache-2.0
#include "glider/netcdf/deployment_metadata.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "glider/config/toml_document.hpp"
#include "glider/config/value_limits.hpp"
#include "glider/utc_time.hpp"

namespace glider::netcdf {
namespace {

using config::ConfigError;
using config::TomlDocument;

// OG1.0 vocabularies (OceanGlidersCommunity/OG-format-user-manual,
// vocabularyCollection/*.md) and the OG1.0 id's data modes (OG_Format-v1.0.0.adoc,
// "OG1.0 file naming convention" and the id examples).
const std::vector<Vocabulary> kVocabularies = {
    {"platform.model",
     "vocabularyCollection/platform_model.md",
     {"Seaglider", "iRobot Seaglider M1", "UoW Seaglider M1", "KM Seaglider M1", "HYD Seaglider M1", "UoW Seaglider M6",
      "Slocum", "Slocum G1", "Slocum G2", "Slocum G3", "Seaexplorer", "Seaexplorer X2", "Seaexplorer X3",
      "Seaexplorer X3 shallow", "SIO Spray", "SIO Spray2", "OceanScout"}},
    {"principal_investigator.role",
     "vocabularyCollection/contributors_role.md",
     {"glider pilot", "principal operator", "operator", "principal investigator", "scientist", "data manager",
      "data curator"}},
    {"operator.role",
     "vocabularyCollection/contributors_role.md",
     {"glider pilot", "principal operator", "operator", "principal investigator", "scientist", "data manager",
      "data curator"}},
    {"dataset.data_mode", "OG_Format-v1.0.0.adoc (id = <platform_serial>_<start_date>_<data_mode>)", {"R", "delayed"}},
};

bool same_term(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

class Reader {
 public:
  explicit Reader(const TomlDocument& doc) : doc_(doc) {}

  // A required key: its absence is named with the line of its table (the
  // place the user has to add it), or the file's first line without the table.
  void require(std::string_view key) const {
    if (doc_.has(key)) return;
    const std::string table(key.substr(0, key.find('.')));
    const std::string where = doc_.has(table) ? doc_.where(table) : doc_.source() + ":1";
    throw ConfigError(where + ": " + std::string(key) + ": missing required key (add it to [" + table + "])");
  }
  std::string text(std::string_view key) const {
    require(key);
    std::string value = doc_.string(key);
    if (value.find_first_not_of(" \t") == std::string::npos) doc_.fail(key, "empty value");
    return value;
  }
  std::string text_or(std::string_view key, std::string fallback) const { return doc_.string_or(key, fallback); }
  double number(std::string_view key, double min, double max) const {
    require(key);
    return doc_.number(key, config::Range{min, max, ""});
  }
  std::string term(std::string_view key, std::string fallback = {}) const {
    if (fallback.empty()) require(key);
    const std::string value = doc_.has(key) ? doc_.string(key) : fallback;
    for (const Vocabulary& vocabulary : kVocabularies) {
      if (vocabulary.key != key) continue;
      for (const std::string& term : vocabulary.terms) {
        if (same_term(term, value)) return term;
      }
      std::string allowed;
      for (const std::string& term : vocabulary.terms) allowed += (allowed.empty() ? "'" : ", '") + term + "'";
      doc_.fail(key, "'" + value + "' is not a term of " + vocabulary.source + " (allowed: " + allowed + ")");
    }
    return value;
  }
  const TomlDocument& doc() const { return doc_; }

 private:
  const TomlDocument& doc_;
};

DeploymentMetadata read(const TomlDocument& doc) {
  const Reader r(doc);
  DeploymentMetadata m;
  m.source = doc.source();
  m.title = r.text_or("dataset.title", "OceanGliders trajectory file");
  m.summary = r.text_or("dataset.summary", "");
  m.institution = r.text("dataset.institution");
  m.project = r.text_or("dataset.project", "");
  m.license = r.text_or("dataset.license", "");
  m.naming_authority = r.text_or("dataset.naming_authority", "");
  m.rtqc_method = r.text("dataset.rtqc_method");
  m.data_mode = r.term("dataset.data_mode");

  m.platform_serial = r.text("platform.serial_number");
  m.platform_name = r.text_or("platform.name", m.platform_serial);
  m.platform_model = r.term("platform.model");
  m.platform_maker = r.text_or("platform.maker", "");
  r.require("platform.wmo_id");
  m.wmo_id = doc.string("platform.wmo_id");  // may be " " before the DAC assigns one
  m.depth_rating_m = r.number("platform.depth_rating_m", 1.0, 11000.0);

  const std::string time = r.text("deployment.time");
  m.deployment_time_s = parse_utc(time);
  if (!std::isfinite(m.deployment_time_s)) doc.fail("deployment.time", "'" + time + "' is not YYYY-MM-DDTHH:MM:SSZ");
  m.deployment_latitude = r.number("deployment.latitude", -90.0, 90.0);
  m.deployment_longitude = r.number("deployment.longitude", -180.0, 180.0);
  m.site = r.text_or("deployment.site", "");

  m.pi_name = r.text("principal_investigator.name");
  m.pi_email = r.text("principal_investigator.email");
  if (m.pi_email.find('@') == std::string::npos) doc.fail("principal_investigator.email", "not an e-mail address");
  m.pi_role = r.term("principal_investigator.role", "principal investigator");
  m.operator_institution = r.text("operator.institution");
  m.operator_role = r.term("operator.role", "operator");

  m.ctd_model = r.text("ctd.model");
  m.ctd_serial = r.text("ctd.serial_number");
  m.ctd_maker = r.text_or("ctd.maker", "");
  m.ctd_model_vocabulary = r.text_or("ctd.model_vocabulary", "");
  m.ctd_calibration_date = r.text_or("ctd.calibration_date", "");
  if (!m.ctd_calibration_date.empty() && !std::isfinite(parse_utc(m.ctd_calibration_date + "T00:00:00Z"))) {
    doc.fail("ctd.calibration_date", "'" + m.ctd_calibration_date + "' is not YYYY-MM-DD");
  }
  m.ctd_pumped = doc.boolean_or("ctd.pumped", true);
  doc.reject_unknown_keys();
  return m;
}

}  // namespace

const std::vector<Vocabulary>& metadata_vocabularies() { return kVocabularies; }

DeploymentMetadata load_deployment_metadata(const std::filesystem::path& path) {
  return read(TomlDocument::load(path));
}

DeploymentMetadata parse_deployment_metadata(std::string_view text, const std::string& source_name) {
  return read(TomlDocument::parse(text, source_name));
}

double parse_utc(std::string_view text) {
  const utc::Parsed parsed = utc::parse_iso(text, utc::Rules{1970, 9999, 0});
  return parsed.ok ? parsed.seconds() : std::numeric_limits<double>::quiet_NaN();
}

std::string format_utc_compact(double seconds) { return utc::format_compact(seconds); }
std::string format_utc_iso(double seconds) { return utc::format_iso(seconds); }

}  // namespace glider::netcdf
