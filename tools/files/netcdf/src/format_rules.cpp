// SPDX-License-Identifier: Apache-2.0
// The rule table. Sources:
//   [OG1]  OceanGliders format v1.0.0, OceanGlidersCommunity/OG-format-user-manual
//          OG_Format-v1.0.0.adoc (commit b910fb17f21fb7a8ee7cd9ef402d77550eb45b80); sections as named.
//   [OGV]  the same repository's vocabularyCollection/*.md (phase.md 02f06eab, platform_model.md 146fc772).
//   [IOOS] IOOS NGDAC NetCDF File Format Version 2, ioos/glider-dac
//          _docs/NGDAC-NetCDF-File-Format-Version-2.md (commit 8440af0a9f81363142691fad89244e22ea9ab38f).
//   [CF]   CF conventions 1.6/1.10, 5 "Coordinate systems" (coordinate variables have no missing values).
#include "glider/netcdf/format_rules.hpp"

#include <array>

namespace glider::netcdf {
namespace {

using F = Format;
using K = RuleKind;

constexpr const char* kIoosQcAttributes =
    "_FillValue flag_meanings flag_values long_name standard_name valid_max valid_min";
constexpr const char* kIoosSeriesAttributes =
    "_FillValue ancillary_variables long_name observation_type platform standard_name units valid_max valid_min";
constexpr const char* kIoosCtdAttributes =
    "_FillValue accuracy ancillary_variables instrument long_name observation_type platform precision resolution "
    "standard_name units valid_max valid_min";
constexpr const char* kIoosScalarAttributes = "_FillValue comment long_name observation_type standard_name units";

constexpr std::array kRules = std::to_array<Rule>({
    // ---- OG1.0: global attributes (mandatory rows of [OG1] "Global attributes") ----
    {F::kOg1, "OG1-G01", K::kGlobalAttribute, "", "title", "", "mandatory", "[OG1] Global attributes"},
    {F::kOg1, "OG1-G02", K::kGlobalAttribute, "", "platform", "", "mandatory", "[OG1] Global attributes"},
    {F::kOg1, "OG1-G03", K::kGlobalAttribute, "", "platform_vocabulary", "", "mandatory", "[OG1] Global attributes"},
    {F::kOg1, "OG1-G04", K::kGlobalAttribute, "", "id", "", "mandatory", "[OG1] Global attributes"},
    {F::kOg1, "OG1-G05", K::kGlobalAttribute, "", "contributor_name", "", "mandatory (PI)", "[OG1] Global attributes"},
    {F::kOg1, "OG1-G06", K::kGlobalAttribute, "", "contributor_email", "", "mandatory (PI)", "[OG1] Global attributes"},
    {F::kOg1, "OG1-G07", K::kGlobalAttribute, "", "contributor_role", "", "mandatory (PI)", "[OG1] Global attributes"},
    {F::kOg1, "OG1-G08", K::kGlobalAttribute, "", "contributor_role_vocabulary", "", "mandatory (PI)",
     "[OG1] Global attributes"},
    {F::kOg1, "OG1-G09", K::kGlobalAttribute, "", "contributing_institutions", "", "mandatory (operator)",
     "[OG1] Global attributes"},
    {F::kOg1, "OG1-G10", K::kGlobalAttribute, "", "contributing_institutions_role", "", "mandatory (operator)",
     "[OG1] Global attributes"},
    {F::kOg1, "OG1-G11", K::kGlobalAttribute, "", "contributing_institutions_role_vocabulary", "",
     "mandatory (operator)", "[OG1] Global attributes"},
    {F::kOg1, "OG1-G12", K::kGlobalAttribute, "", "rtqc_method", "", "mandatory", "[OG1] Global attributes"},
    {F::kOg1, "OG1-G13", K::kGlobalAttribute, "", "start_date", "@compact", "mandatory",
     "[OG1] Global attributes (YYYYmmddTHHMMss)"},
    {F::kOg1, "OG1-G14", K::kGlobalAttribute, "", "date_created", "@compact", "mandatory",
     "[OG1] Global attributes (YYYYmmddTHHMMss)"},
    {F::kOg1, "OG1-G15", K::kGlobalAttribute, "", "featureType", "trajectory", "mandatory",
     "[OG1] Global attributes (fixed value)"},
    {F::kOg1, "OG1-G16", K::kGlobalAttribute, "", "Conventions", "~OG-1.0", "mandatory", "[OG1] Global attributes"},
    // ---- OG1.0: dimension and coordinates ----
    {F::kOg1, "OG1-D01", K::kDimension, "N_MEASUREMENTS", "", "unlimited", "mandatory",
     "[OG1] Dimension and definition"},
    {F::kOg1, "OG1-C01", K::kVariable, "TIME", "", "double(N_MEASUREMENTS)", "mandatory", "[OG1] Coordinates"},
    {F::kOg1, "OG1-C02", K::kAttributes, "TIME", "long_name calendar units _FillValue valid_min valid_max", "",
     "mandatory", "[OG1] Coordinates"},
    {F::kOg1, "OG1-C03", K::kAttributeValue, "TIME", "units", "seconds since 1970-01-01T00:00:00Z", "mandatory",
     "[OG1] Coordinates"},
    {F::kOg1, "OG1-C04", K::kValidRange, "TIME", "", "", "mandatory",
     "[OG1] Coordinates (valid_min 1e9, valid_max 4e9)"},
    {F::kOg1, "OG1-C05", K::kVariable, "LATITUDE", "", "double(N_MEASUREMENTS)", "mandatory", "[OG1] Coordinates"},
    {F::kOg1, "OG1-C06", K::kAttributes, "LATITUDE", "long_name standard_name units _FillValue valid_min valid_max", "",
     "mandatory", "[OG1] Coordinates"},
    {F::kOg1, "OG1-C07", K::kAttributeValue, "LATITUDE", "standard_name", "latitude", "mandatory", "[OG1] Coordinates"},
    {F::kOg1, "OG1-C08", K::kValidRange, "LATITUDE", "", "", "mandatory", "[OG1] Coordinates"},
    {F::kOg1, "OG1-C09", K::kVariable, "LONGITUDE", "", "double(N_MEASUREMENTS)", "mandatory", "[OG1] Coordinates"},
    {F::kOg1, "OG1-C10", K::kAttributes, "LONGITUDE", "long_name standard_name units _FillValue valid_min valid_max",
     "", "mandatory", "[OG1] Coordinates"},
    {F::kOg1, "OG1-C11", K::kAttributeValue, "LONGITUDE", "standard_name", "longitude", "mandatory",
     "[OG1] Coordinates"},
    {F::kOg1, "OG1-C12", K::kValidRange, "LONGITUDE", "", "", "mandatory", "[OG1] Coordinates"},
    {F::kOg1, "OG1-C13", K::kVariable, "DEPTH", "", "double(N_MEASUREMENTS)", "mandatory", "[OG1] Coordinates"},
    {F::kOg1, "OG1-C14", K::kAttributes, "DEPTH", "long_name standard_name units _FillValue valid_min valid_max", "",
     "mandatory", "[OG1] Coordinates"},
    {F::kOg1, "OG1-C15", K::kAttributeValue, "DEPTH", "standard_name", "depth", "mandatory", "[OG1] Coordinates"},
    {F::kOg1, "OG1-C16", K::kValidRange, "DEPTH", "", "", "mandatory", "[OG1] Coordinates"},
    // ---- OG1.0: GPS ----
    {F::kOg1, "OG1-P01", K::kVariable, "TIME_GPS", "", "double(N_MEASUREMENTS)", "mandatory", "[OG1] GPS variables"},
    {F::kOg1, "OG1-P02", K::kAttributes, "TIME_GPS", "long_name calendar units _FillValue valid_min valid_max", "",
     "mandatory", "[OG1] GPS variables"},
    {F::kOg1, "OG1-P03", K::kVariable, "LATITUDE_GPS", "", "double(N_MEASUREMENTS)", "mandatory",
     "[OG1] GPS variables"},
    {F::kOg1, "OG1-P04", K::kAttributes, "LATITUDE_GPS", "long_name standard_name units _FillValue valid_min valid_max",
     "", "mandatory", "[OG1] GPS variables"},
    {F::kOg1, "OG1-P05", K::kValidRange, "LATITUDE_GPS", "", "", "mandatory", "[OG1] GPS variables"},
    {F::kOg1, "OG1-P06", K::kVariable, "LONGITUDE_GPS", "", "double(N_MEASUREMENTS)", "mandatory",
     "[OG1] GPS variables"},
    {F::kOg1, "OG1-P07", K::kAttributes, "LONGITUDE_GPS",
     "long_name standard_name units _FillValue valid_min valid_max", "", "mandatory", "[OG1] GPS variables"},
    {F::kOg1, "OG1-P08", K::kValidRange, "LONGITUDE_GPS", "", "", "mandatory", "[OG1] GPS variables"},
    // ---- OG1.0: trajectory, platform, deployment ----
    {F::kOg1, "OG1-T01", K::kVariable, "TRAJECTORY", "", "string()", "mandatory", "[OG1] Trajectory Name"},
    {F::kOg1, "OG1-T02", K::kAttributeValue, "TRAJECTORY", "cf_role", "trajectory_id", "mandatory",
     "[OG1] Trajectory Name"},
    {F::kOg1, "OG1-T03", K::kAttributes, "TRAJECTORY", "long_name", "", "mandatory", "[OG1] Trajectory Name"},
    {F::kOg1, "OG1-M01", K::kVariable, "WMO_IDENTIFIER", "", "string()", "mandatory", "[OG1] Platform information"},
    {F::kOg1, "OG1-M02", K::kVariable, "PLATFORM_MODEL", "", "string()", "mandatory", "[OG1] Platform information"},
    {F::kOg1, "OG1-M03", K::kAttributes, "PLATFORM_MODEL", "long_name platform_model_vocabulary", "", "mandatory",
     "[OG1] Platform information"},
    {F::kOg1, "OG1-M04", K::kVocabulary, "PLATFORM_MODEL", "", "platform.model", "mandatory",
     "[OGV] platform_model.md"},
    {F::kOg1, "OG1-M05", K::kVariable, "PLATFORM_SERIAL_NUMBER", "", "string()", "mandatory",
     "[OG1] Platform information"},
    {F::kOg1, "OG1-M06", K::kVariable, "DEPLOYMENT_TIME", "", "double()", "mandatory", "[OG1] Deployment information"},
    {F::kOg1, "OG1-M07", K::kAttributes, "DEPLOYMENT_TIME", "long_name standard_name calendar units", "", "mandatory",
     "[OG1] Deployment information"},
    {F::kOg1, "OG1-M08", K::kVariable, "DEPLOYMENT_LATITUDE", "", "double()", "mandatory",
     "[OG1] Deployment information"},
    {F::kOg1, "OG1-M09", K::kVariable, "DEPLOYMENT_LONGITUDE", "", "double()", "mandatory",
     "[OG1] Deployment information"},
    // ---- OG1.0: sensors and parameters ----
    {F::kOg1, "OG1-S01", K::kSensors, "SENSOR_*",
     "sensor_type_vocabulary long_name sensor_model sensor_model_vocabulary", "", "mandatory",
     "[OG1] Sensor information"},
    {F::kOg1, "OG1-S02", K::kParams, "<PARAM>", "long_name units vocabulary _FillValue coordinates sensor", "",
     "mandatory", "[OG1] Geophysical variables"},
    {F::kOg1, "OG1-S03", K::kSensorReferences, "<PARAM>", "sensor", "", "mandatory",
     "[OG1] Geophysical variables (sensor = \"SENSOR_<sensor_type>_<sensor_serial_number>\")"},
    {F::kOg1, "OG1-S04", K::kAncillary, "*", "ancillary_variables", "", "mandatory",
     "[OG1] Geophysical variables; [CF] 3.4 Ancillary data"},
    {F::kOg1, "OG1-H01", K::kVocabulary, "PHASE", "", "phase", "highly desirable",
     "[OG1] Phase variable; [OGV] phase.md"},
    // ---- IOOS NGDAC v2: global attributes ("all attributes listed below are REQUIRED") ----
    {F::kIoos, "IOOS-G01", K::kGlobalAttribute, "", "Conventions", "CF-1.6", "required", "[IOOS] Global Attributes"},
    {F::kIoos, "IOOS-G02", K::kGlobalAttribute, "", "Metadata_Conventions", "CF-1.6, Unidata Dataset Discovery v1.0",
     "required", "[IOOS] Global Attributes"},
    {F::kIoos, "IOOS-G03", K::kGlobalAttribute, "", "format_version", "IOOS_Glider_NetCDF_v2.0.nc", "required",
     "[IOOS] Global Attributes"},
    {F::kIoos, "IOOS-G04", K::kGlobalAttribute, "",
     "acknowledgment comment contributor_name contributor_role creator_email creator_name creator_url date_created "
     "date_issued date_modified history id institution keywords keywords_vocabulary license metadata_link "
     "naming_authority platform_type processing_level project publisher_email publisher_name publisher_url references "
     "sea_name source standard_name_vocabulary summary title wmo_id",
     "", "required", "[IOOS] Global Attributes (acknowledgment spelled as in the v2.0 template)"},
    {F::kIoos, "IOOS-G05", K::kGlobalText, "", "", "", "required", "[IOOS] Global Attributes, caveat 3"},
    // ---- IOOS: dimensions ----
    {F::kIoos, "IOOS-D01", K::kDimension, "time", "", "", "required", "[IOOS] Dimensions"},
    {F::kIoos, "IOOS-D02", K::kDimension, "traj_strlen", "", "", "required", "[IOOS] Dimensions"},
    // ---- IOOS: trajectory and time series ----
    {F::kIoos, "IOOS-V01", K::kVariable, "trajectory", "", "char(traj_strlen)", "required", "[IOOS] trajectory"},
    {F::kIoos, "IOOS-V02", K::kAttributeValue, "trajectory", "cf_role", "trajectory_id", "required",
     "[IOOS] trajectory"},
    {F::kIoos, "IOOS-V03", K::kVariable, "time", "", "double(time)", "required", "[IOOS] time"},
    {F::kIoos, "IOOS-V04", K::kAttributes, "time",
     "ancillary_variables calendar long_name observation_type standard_name units", "", "required", "[IOOS] time"},
    {F::kIoos, "IOOS-V05", K::kNoFillValue, "time", "", "", "required", "[IOOS] time; [CF] 5 coordinate variables"},
    {F::kIoos, "IOOS-V06", K::kVariable, "lat", "", "double(time)", "required", "[IOOS] lat"},
    {F::kIoos, "IOOS-V07", K::kAttributes, "lat", kIoosSeriesAttributes, "", "required", "[IOOS] lat"},
    {F::kIoos, "IOOS-V08", K::kValidRange, "lat", "", "", "required", "[IOOS] lat"},
    {F::kIoos, "IOOS-V09", K::kVariable, "lon", "", "double(time)", "required", "[IOOS] lon"},
    {F::kIoos, "IOOS-V10", K::kAttributes, "lon", kIoosSeriesAttributes, "", "required", "[IOOS] lon"},
    {F::kIoos, "IOOS-V11", K::kValidRange, "lon", "", "", "required", "[IOOS] lon"},
    {F::kIoos, "IOOS-V12", K::kVariable, "pressure", "", "double(time)", "required", "[IOOS] pressure"},
    {F::kIoos, "IOOS-V13", K::kAttributes, "pressure", kIoosCtdAttributes, "", "required", "[IOOS] pressure"},
    {F::kIoos, "IOOS-V14", K::kAttributeValue, "pressure", "standard_name", "sea_water_pressure", "required",
     "[IOOS] pressure"},
    {F::kIoos, "IOOS-V15", K::kVariable, "depth", "", "double(time)", "required", "[IOOS] depth"},
    {F::kIoos, "IOOS-V16", K::kAttributes, "depth", kIoosCtdAttributes, "", "required", "[IOOS] depth"},
    {F::kIoos, "IOOS-V17", K::kAttributeValue, "depth", "standard_name", "depth", "required", "[IOOS] depth"},
    {F::kIoos, "IOOS-V18", K::kVariable, "temperature", "", "double(time)", "required", "[IOOS] temperature"},
    {F::kIoos, "IOOS-V19", K::kAttributes, "temperature", kIoosCtdAttributes, "", "required", "[IOOS] temperature"},
    {F::kIoos, "IOOS-V20", K::kAttributeValue, "temperature", "standard_name", "sea_water_temperature", "required",
     "[IOOS] temperature"},
    {F::kIoos, "IOOS-V21", K::kVariable, "conductivity", "", "double(time)", "required", "[IOOS] conductivity"},
    {F::kIoos, "IOOS-V22", K::kAttributes, "conductivity", kIoosCtdAttributes, "", "required", "[IOOS] conductivity"},
    {F::kIoos, "IOOS-V23", K::kVariable, "salinity", "", "double(time)", "required", "[IOOS] salinity"},
    {F::kIoos, "IOOS-V24", K::kAttributes, "salinity", kIoosCtdAttributes, "", "required", "[IOOS] salinity"},
    {F::kIoos, "IOOS-V25", K::kVariable, "density", "", "double(time)", "required", "[IOOS] density"},
    {F::kIoos, "IOOS-V26", K::kAttributes, "density", kIoosCtdAttributes, "", "required", "[IOOS] density"},
    {F::kIoos, "IOOS-Q01", K::kVariable,
     "time_qc lat_qc lon_qc pressure_qc depth_qc temperature_qc conductivity_qc "
     "salinity_qc density_qc",
     "", "byte(time)", "required", "[IOOS] <variable>_qc"},
    {F::kIoos, "IOOS-Q02", K::kAttributes,
     "time_qc lat_qc lon_qc pressure_qc depth_qc temperature_qc conductivity_qc "
     "salinity_qc density_qc",
     kIoosQcAttributes, "", "required", "[IOOS] <variable>_qc"},
    {F::kIoos, "IOOS-Q03", K::kAncillary, "*", "ancillary_variables", "", "required",
     "[IOOS] Variables (ancillary_variables); [CF] 3.4"},
    // ---- IOOS: profile and depth-averaged current scalars ----
    {F::kIoos, "IOOS-R01", K::kVariable, "profile_id", "", "int()", "required", "[IOOS] profile_id"},
    {F::kIoos, "IOOS-R02", K::kAttributes, "profile_id", "_FillValue comment long_name valid_max valid_min", "",
     "required", "[IOOS] profile_id"},
    {F::kIoos, "IOOS-R03", K::kValidRange, "profile_id", "", "", "required",
     "[IOOS] profile_id (numbering begins at 1)"},
    {F::kIoos, "IOOS-R04", K::kVariable, "profile_time profile_lat profile_lon time_uv lat_uv lon_uv u v", "",
     "double()", "required", "[IOOS] profile_time .. v"},
    {F::kIoos, "IOOS-R05", K::kAttributes, "profile_time profile_lat profile_lon time_uv lat_uv lon_uv u v",
     kIoosScalarAttributes, "", "required", "[IOOS] profile_time .. v"},
    {F::kIoos, "IOOS-R06", K::kVariable,
     "profile_time_qc profile_lat_qc profile_lon_qc time_uv_qc lat_uv_qc lon_uv_qc u_qc v_qc", "", "byte()", "required",
     "[IOOS] profile_time_qc .. v_qc"},
    {F::kIoos, "IOOS-R07", K::kAttributes,
     "profile_time_qc profile_lat_qc profile_lon_qc time_uv_qc lat_uv_qc lon_uv_qc u_qc v_qc", kIoosQcAttributes, "",
     "required", "[IOOS] profile_time_qc .. v_qc"},
    {F::kIoos, "IOOS-R08", K::kValidRange, "profile_lat profile_lon lat_uv lon_uv u v", "", "", "required",
     "[IOOS] profile_lat .. v (valid_min, valid_max)"},
    // ---- IOOS: containers ----
    {F::kIoos, "IOOS-C01", K::kVariable, "platform", "", "int()", "required", "[IOOS] platform"},
    {F::kIoos, "IOOS-C02", K::kAttributes, "platform", "_FillValue id instrument long_name type wmo_id", "",
     "required (all but comment)", "[IOOS] platform"},
    {F::kIoos, "IOOS-C03", K::kVariable, "instrument_ctd", "", "int()", "required", "[IOOS] instrument_ctd"},
    {F::kIoos, "IOOS-C04", K::kAttributeValue, "instrument_ctd", "platform", "platform", "required",
     "[IOOS] instrument_ctd (all attributes but platform are optional)"},
});

}  // namespace

std::string_view to_string(Format format) { return format == Format::kOg1 ? "OG1.0" : "IOOS NGDAC v2"; }

std::span<const Rule> format_rules() { return kRules; }

}  // namespace glider::netcdf
