// SPDX-License-Identifier: Apache-2.0
// OG1.0 (OceanGliders format v1.0.0, OG_Format-v1.0.0.adoc of
// OceanGlidersCommunity/OG-format-user-manual): a NetCDF-4 trajectory file,
// dimension N_MEASUREMENTS (unlimited), coordinates TIME/LATITUDE/LONGITUDE/
// DEPTH, the GPS fixes, PHASE, platform, deployment and sensor variables.
#include <netcdf.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "glider/netcdf/writers.hpp"
#include "variable_writer.hpp"

namespace glider::netcdf {
namespace {

constexpr double kFill = -9999.9;       // OG1.0's _FillValue of the coordinates
constexpr float kFloatFill = -9999.9F;  // the same for the float parameters
const char* const kVocab = "https://vocab.nerc.ac.uk/collection/OG1/current/";
const char* const kCoordinates = "TIME LONGITUDE LATITUDE DEPTH";

class Og1Writer {
 public:
  Og1Writer(DatasetSink& file, const WriteContext& context)
      : f_(file),
        c_(context),
        t_(*context.trajectory),
        m_(context.metadata != nullptr ? *context.metadata : kNoMetadata),
        has_metadata_(context.metadata != nullptr) {}

  void write() {
    dim_ = f_.def_dim("N_MEASUREMENTS", 0);
    chunk_ = std::max<std::size_t>(1, std::min<std::size_t>(t_.size(), 1U << 20));
    globals();
    coordinates();
    gps();
    parameters();
    phase_and_profile();
    if (c_.products != nullptr) flight_model();
    if (has_metadata_) scalars();
    f_.end_define();
    for (const auto& [var, values] : doubles_) f_.put(var, values);
    for (const auto& [var, values] : bytes_) f_.put(var, values);
    for (const auto& [var, values] : ints_) f_.put(var, values);
    for (const auto& [var, value] : strings_) f_.put_string(var, value);
    for (const auto& [var, value] : scalar_doubles_) f_.put_scalar(var, value);
    for (const auto& [var, value] : scalar_ints_) f_.put_scalar_int(var, value);
  }

 private:
  int series(const std::string& name, int type, const std::vector<double>& values, double fill) {
    const int var = f_.def_var(name, type, {dim_});
    f_.set_chunking(var, chunk_);
    f_.put_att(var, "_FillValue", type, {fill});
    doubles_.emplace_back(var, with_fill(values, fill));
    return var;
  }
  // An OG1.0 <PARAM>_QC: no QC is applied (0) where there is a value.
  void qc(const std::string& name, const std::vector<double>& values) {
    const int var = f_.def_var(name + "_QC", NC_BYTE, {dim_});
    f_.set_chunking(var, chunk_);
    f_.put_att(var, "long_name", "quality flag");
    f_.put_att(var, "valid_range", NC_BYTE, {0, 4});
    f_.put_att(var, "flag_values", NC_BYTE, {0, 1, 2, 3, 4});
    f_.put_att(var, "flag_meanings", "no_QC_has_been_applied good_data probably_good_data probably_bad_data bad_data");
    f_.put_att(var, "comment", "0 (no QC applied) where the variable has a value, -127 (the fill) where it has none");
    bytes_.emplace_back(var, qc_flags(values, 0, -127));
  }
  int string_scalar(const std::string& name, const std::string& value, const std::string& long_name) {
    const int var = f_.def_var(name, NC_STRING, {});
    f_.put_att(var, "long_name", long_name);
    strings_.emplace_back(var, value);
    return var;
  }

  void globals() {
    const double start = t_.size() ? t_.time_s.front() : m_.deployment_time_s;
    const double end = t_.size() ? t_.time_s.back() : m_.deployment_time_s;
    auto g = [&](const char* name, const std::string& value) {
      if (!value.empty()) f_.put_att(-1, name, value);
    };
    // Without the deployment metadata (an in-memory dataset of a log): only
    // what the data say; the elements the metadata file gives are left out.
    auto gm = [&](const char* name, const std::string& value) {
      if (has_metadata_) g(name, value);
    };
    g("title", m_.title);
    g("platform", "sub-surface gliders");
    g("platform_vocabulary", "https://vocab.nerc.ac.uk/collection/L06/current/27/");
    gm("id", og1_id(m_));
    g("naming_authority", m_.naming_authority);
    g("institution", m_.institution);
    gm("internal_mission_identifier", m_.platform_name + "_" + format_utc_compact(m_.deployment_time_s));
    double lat_min = INFINITY, lat_max = -INFINITY, lon_min = INFINITY, lon_max = -INFINITY, z_min = INFINITY,
           z_max = -INFINITY;
    for (std::size_t i = 0; i < t_.size(); ++i) {
      if (std::isfinite(t_.latitude[i]))
        lat_min = std::min(lat_min, t_.latitude[i]), lat_max = std::max(lat_max, t_.latitude[i]);
      if (std::isfinite(t_.longitude[i]))
        lon_min = std::min(lon_min, t_.longitude[i]), lon_max = std::max(lon_max, t_.longitude[i]);
      if (std::isfinite(t_.depth_m[i])) z_min = std::min(z_min, t_.depth_m[i]), z_max = std::max(z_max, t_.depth_m[i]);
    }
    if (lat_min <= lat_max) {
      f_.put_att(-1, "geospatial_lat_min", lat_min);
      f_.put_att(-1, "geospatial_lat_max", lat_max);
      f_.put_att(-1, "geospatial_lon_min", lon_min);
      f_.put_att(-1, "geospatial_lon_max", lon_max);
    }
    if (z_min <= z_max) {
      f_.put_att(-1, "geospatial_vertical_min", z_min);
      f_.put_att(-1, "geospatial_vertical_max", z_max);
    }
    if (t_.size() || has_metadata_) {
      g("time_coverage_start", format_utc_compact(start));
      g("time_coverage_end", format_utc_compact(end));
    }
    g("site", m_.site);
    g("project", m_.project);
    g("contributor_name", m_.pi_name);
    g("contributor_email", m_.pi_email);
    g("contributor_role", m_.pi_role);
    gm("contributor_role_vocabulary",
       "https://github.com/OceanGlidersCommunity/OG-format-user-manual/blob/main/vocabularyCollection/"
       "contributors_role.md");
    g("contributing_institutions", m_.operator_institution);
    g("contributing_institutions_role", m_.operator_role);
    gm("contributing_institutions_role_vocabulary",
       "https://github.com/OceanGlidersCommunity/OG-format-user-manual/blob/main/vocabularyCollection/"
       "contributors_role.md");
    g("rtqc_method", m_.rtqc_method);
    gm("start_date", format_utc_compact(m_.deployment_time_s));
    g("date_created", format_utc_compact(c_.created_s));
    g("featureType", "trajectory");
    g("Conventions", "CF-1.10, ACDD-1.3, OG-1.0");
    g("license", m_.license);
    g("summary", m_.summary);
    g("history", c_.history);
    g("source", "Slocum glider binary files converted by glider-convert (this project)");
    g("comment", "PHASE and PROFILE_NUMBER from the project's phase segmentation (docs/netcdf.md)");
    if (!has_metadata_) {
      g("glider_no_metadata",
        "no deployment metadata file given: the platform, deployment, contributor and sensor elements OG1.0 "
        "requires are not in this dataset (docs/netcdf.md, the deployment metadata file)");
    }
  }

  void coordinates() {
    int v = series("TIME", NC_DOUBLE, t_.time_s, -1.0);
    f_.put_att(v, "long_name", "Time elapsed since 1970-01-01T00:00:00Z");
    f_.put_att(v, "standard_name", "time");
    f_.put_att(v, "calendar", "gregorian");
    f_.put_att(v, "units", "seconds since 1970-01-01T00:00:00Z");
    f_.put_att(v, "axis", "T");
    f_.put_att(v, "valid_min", 1e9);
    f_.put_att(v, "valid_max", 4e9);
    f_.put_att(v, "ancillary_variables", "TIME_QC");
    f_.put_att(v, "interpolation_methodology", "none: the flight computer's m_present_time of each cycle");
    f_.put_att(v, "time_vocabulary", std::string(kVocab) + "TIME/");
    qc("TIME", t_.time_s);
    const char* dr =
        "the glider's dead-reckoned position (m_lat, m_lon: reset at each GPS fix), linear in time "
        "between logged values";
    v = position("LATITUDE", t_.latitude, "Latitude north (WGS84)", dr);
    f_.put_att(v, "axis", "Y");
    f_.put_att(v, "latitude_vocabulary", std::string(kVocab) + "LAT/");
    v = position("LONGITUDE", t_.longitude, "longitude of each measurement and GPS location", dr);
    f_.put_att(v, "axis", "X");
    f_.put_att(v, "longitude_vocabulary", std::string(kVocab) + "LON/");
    v = series("DEPTH", NC_DOUBLE, t_.depth_m, kFill);
    f_.put_att(v, "long_name",
               "Depth below surface of the water body by unknown instrument and correction to zero at sea level "
               "using unspecified algorithm.");
    f_.put_att(v, "standard_name", "depth");
    f_.put_att(v, "units", "m");
    f_.put_att(v, "positive", "down");
    f_.put_att(v, "axis", "Z");
    f_.put_att(v, "valid_min", 0.0);
    f_.put_att(v, "valid_max", 10000.0);
    f_.put_att(v, "ancillary_variables", "DEPTH_QC");
    f_.put_att(v, "interpolation_methodology", "none");
    f_.put_att(v, "comment", "from " + t_.depth_source + " as logged (glider-convert's CSV column)");
    f_.put_att(v, "depth_vocabulary", std::string(kVocab) + "DEPTH/");
    qc("DEPTH", t_.depth_m);
  }

  void gps() {
    std::vector<double> time(t_.size(), NAN);
    for (std::size_t i = 0; i < t_.size(); ++i) {
      if (std::isfinite(t_.gps_latitude[i])) time[i] = t_.time_s[i];
    }
    int v = series("TIME_GPS", NC_DOUBLE, time, -1.0);
    f_.put_att(v, "long_name", "time of each GPS location");
    f_.put_att(v, "calendar", "gregorian");
    f_.put_att(v, "units", "seconds since 1970-01-01T00:00:00Z");
    f_.put_att(v, "valid_min", 1e9);
    f_.put_att(v, "valid_max", 4e9);
    f_.put_att(v, "ancillary_variables", "TIME_GPS_QC");
    qc("TIME_GPS", time);
    position("LATITUDE_GPS", t_.gps_latitude, "latitude of each GPS location",
             "m_gps_lat (NMEA ddmm.mmmm) in decimal degrees where a new fix was logged; 69696969 (no fix) and the "
             "log's repeats of the last fix are the fill");
    position("LONGITUDE_GPS", t_.gps_longitude, "longitude of each GPS location",
             "m_gps_lon (NMEA dddmm.mmmm) in decimal degrees");
  }

  // A latitude (name contains "LAT") or longitude with its OG1.0 attributes and QC.
  int position(const std::string& name, const std::vector<double>& values, const char* long_name, const char* how) {
    const bool latitude = name.find("LAT") != std::string::npos;
    const double limit = latitude ? 90.0 : 180.0;
    const int v = series(name, NC_DOUBLE, values, kFill);
    f_.put_att(v, "long_name", long_name);
    f_.put_att(v, "standard_name", latitude ? "latitude" : "longitude");
    f_.put_att(v, "units", latitude ? "degrees_north" : "degrees_east");
    f_.put_att(v, "valid_min", -limit);
    f_.put_att(v, "valid_max", limit);
    f_.put_att(v, "ancillary_variables", name + "_QC");
    f_.put_att(v, name.find("GPS") != std::string::npos ? "comment" : "interpolation_methodology", how);
    qc(name, values);
    return v;
  }

  // A geophysical <PARAM> (float) with the OG1.0 attributes.
  void param(const std::string& name, const std::vector<double>& values, const char* long_name,
             const char* standard_name, const char* units, const char* source, bool ctd) {
    const int v = series(name, NC_FLOAT, values, kFloatFill);
    f_.put_att(v, "long_name", long_name);
    if (standard_name[0] != '\0') f_.put_att(v, "standard_name", standard_name);
    f_.put_att(v, "units", units);
    // A parameter of the OG1 vocabulary needs its sensor ([OG1] Geophysical
    // variables); the attitude sensor is not in the metadata file, so the
    // attitude is written as an "other measurement" without a vocabulary.
    if (ctd) f_.put_att(v, "vocabulary", std::string(kVocab) + name + "/");
    f_.put_att(v, "coordinates", kCoordinates);
    f_.put_att(v, "ancillary_variables", name + "_QC");
    if (ctd && has_metadata_) f_.put_att(v, "sensor", sensor_name());
    f_.put_att(v, "comment", source);
    qc(name, values);
  }
  std::string sensor_name() const { return "SENSOR_CTD_" + m_.ctd_serial; }

  void parameters() {
    param("PRES", t_.pressure_dbar,
          "Pressure (spatial coordinate) exerted by the water body by profiling pressure "
          "sensor and correction to read zero at sea level",
          "sea_water_pressure", "dbar", "sci_water_pressure (bar) x 10", true);
    param("TEMP", t_.temperature_c, "Temperature of the water body by CTD or STD", "sea_water_temperature",
          "degree_Celsius", "sci_water_temp", true);
    std::vector<double> cndc(t_.conductivity_s_m);
    for (double& x : cndc) x *= 10.0;  // S/m -> mS/cm
    param("CNDC", cndc, "Electrical conductivity of the water body by CTD", "sea_water_electrical_conductivity",
          "mS cm-1", "sci_water_cond (S/m) x 10", true);
    param("PSAL", t_.salinity,
          "Practical salinity of the water body by CTD and computation using UNESCO 1983 "
          "algorithm",
          "sea_water_practical_salinity", "1",
          "PSS-78 from sci_water_cond, sci_water_temp, "
          "sci_water_pressure (model/seawater.hpp)",
          true);
    param("DENSITY", t_.density_kg_m3, "In-situ density of the water body by CTD and computation using TEOS-10",
          "sea_water_density", "kg m-3", "TEOS-10 from the CTD (model/seawater.hpp)", true);
    param("HEADING", t_.heading_deg, "Orientation (horizontal relative to true north) of measurement device {heading}",
          "platform_orientation", "degrees", "m_heading (rad) in degrees", false);
    param("PITCH", t_.pitch_deg, "Orientation (pitch) of measurement platform by inclinometer", "platform_pitch",
          "degrees", "m_pitch (rad) in degrees, + nose up", false);
    param("PUMPED_VOLUME", t_.pumped_cc, "volume pumped out by the buoyancy engine", "", "cm3",
          "m_ballast_pumped (else m_de_oil_vol) as logged, + = water out = lighter: the flight model's input, "
          "read back by this project's tools (docs/netcdf.md)",
          false);
    param("ROLL", t_.roll_deg, "Orientation (roll angle) of measurement platform by inclinometer", "platform_roll",
          "degrees", "m_roll (rad) in degrees, + starboard wing down", false);
  }

  void phase_and_profile() {
    std::vector<double> phase(t_.size());
    for (std::size_t i = 0; i < t_.size(); ++i) phase[i] = og_phase_code(t_.phase[i]);
    int v = f_.def_var("PHASE", NC_BYTE, {dim_});
    f_.set_chunking(v, chunk_);
    f_.put_att(v, "long_name", "behavior of the glider at sea");
    f_.put_att(
        v, "phase_vocabulary",
        "https://github.com/OceanGlidersCommunity/OG-format-user-manual/blob/main/vocabularyCollection/phase.md");
    f_.put_att(v, "flag_values", NC_BYTE, {0, 1, 2, 3, 5});
    f_.put_att(v, "flag_meanings", "unknown ascent descent surfacing inflexion");
    f_.put_att(v, "phase_calculation_method",
               "glider project flightlog::classify_phases: depth rate >= 0.05 m/s with m_depth_state as a hint, "
               "surface above 1 m, short turns bridged (docs/netcdf.md)");
    f_.put_att(v, "phase_calculation_method_vocabulary",
               "https://github.com/OceanGlidersCommunity/OG-format-user-manual");
    f_.put_att(v, "ancillary_variables", "PHASE_QC");
    std::vector<std::int8_t> codes(phase.begin(), phase.end());
    bytes_.emplace_back(v, codes);
    qc("PHASE", phase);
    v = f_.def_var("PROFILE_NUMBER", NC_INT, {dim_});
    f_.set_chunking(v, chunk_);
    f_.put_att(v, "_FillValue", NC_INT, {-1});
    f_.put_att(v, "long_name", "profile number");
    f_.put_att(v, "comment",
               "each dive and each climb spanning >= 3 m is one profile, numbered from 1 in time "
               "order; -1 (fill) outside profiles");
    std::vector<std::int32_t> numbers(t_.profile);
    for (auto& n : numbers) n = n > 0 ? n : -1;
    ints_.emplace_back(v, numbers);
  }

  void product(const std::string& name, const std::vector<double>& values, const char* long_name, const char* units,
               const char* comment) {
    const int v = series(name, NC_FLOAT, values, kFloatFill);
    f_.put_att(v, "long_name", long_name);
    f_.put_att(v, "units", units);
    f_.put_att(v, "coordinates", kCoordinates);
    f_.put_att(v, "comment", comment);
    f_.put_att(v, "flight_model",
               "steady glide at the logged pitch with the net buoyancy of the logged pump volume "
               "(glider project model/steady_glide.hpp PitchGlideSolver), vehicle " +
                   c_.products->vehicle_name);
  }

  void flight_model() {
    const FlightProducts& p = *c_.products;
    product("SPEED_THROUGH_WATER_MODEL", p.speed_m_s, "glider speed through the water from the flight model", "m s-1",
            "along the glide path; dives and climbs only");
    product("ANGLE_OF_ATTACK_MODEL", p.alpha_deg, "angle of attack from the flight model", "degrees",
            "angle between the hull axis and the glide path, + when the path is below the axis");
    product("GLIDE_ANGLE_MODEL", p.glide_angle_deg, "glide path angle from the flight model", "degrees",
            "pitch minus angle of attack: the path below (-) or above (+) the horizontal");
    product("GLIDER_VERT_VELO_MODEL", p.glider_w_m_s,
            "glider vertical velocity through the water from the flight model", "m s-1", "+ up");
    product("GLIDER_VERT_VELO_DZDT", p.measured_w_m_s, "glider vertical velocity from the depth rate", "m s-1",
            "+ up: minus the slope of a line fitted to DEPTH over +-5 s");
    product("VERT_CURR_MODEL", p.water_w_m_s, "vertical velocity of the water", "m s-1",
            "+ up: GLIDER_VERT_VELO_DZDT minus GLIDER_VERT_VELO_MODEL");
    const std::string dac =
        "from the GPS fix before the dive to the fix after it: (GPS displacement minus the "
        "flight model's displacement through the water along m_heading) / time between the fixes";
    product("DEPTH_AVG_CURR_EAST", p.current_east_m_s, "depth-averaged eastward current", "m s-1", dac.c_str());
    product("DEPTH_AVG_CURR_NORTH", p.current_north_m_s, "depth-averaged northward current", "m s-1", dac.c_str());
    const std::string sigma = "1 sigma: GPS fixes " + std::to_string(static_cast<int>(kGpsFixErrorM)) +
                              " m each, model horizontal speed " +
                              std::to_string(static_cast<int>(kSpeedRelativeError * 100)) +
                              " %, the underwater time without a model glide at the mean speed, in quadrature";
    product("DEPTH_AVG_CURR_UNCERTAINTY", p.current_uncertainty_m_s, "uncertainty of the depth-averaged current",
            "m s-1", sigma.c_str());
    f_.put_att(-1, "flight_model_vehicle", p.vehicle_name);
    for (const auto& [key, value] : p.parameters) f_.put_att(-1, "flight_model_" + key, value);
  }

  void scalars() {
    int v = string_scalar("TRAJECTORY", m_.platform_serial + "_" + format_utc_compact(m_.deployment_time_s),
                          "trajectory name");
    f_.put_att(v, "cf_role", "trajectory_id");
    string_scalar("WMO_IDENTIFIER", m_.wmo_id, "wmo id");
    v = string_scalar("PLATFORM_MODEL", m_.platform_model, "model of the glider");
    f_.put_att(v, "platform_model_vocabulary",
               "https://github.com/OceanGlidersCommunity/OG-format-user-manual/blob/main/vocabularyCollection/"
               "platform_model.md");
    string_scalar("PLATFORM_SERIAL_NUMBER", m_.platform_serial, "glider serial number");
    string_scalar("PLATFORM_NAME", m_.platform_name, "Local or nickname of the glider");
    if (!m_.platform_maker.empty()) string_scalar("PLATFORM_MAKER", m_.platform_maker, "glider manufacturer");
    v = f_.def_var("PLATFORM_DEPTH_RATING", NC_INT, {});
    f_.put_att(v, "long_name", "depth limit in meters of the glider for this mission");
    f_.put_att(v, "convention", "positive value expected - e.g. 100m depth = 100");
    scalar_ints_.emplace_back(v, static_cast<int>(std::lround(m_.depth_rating_m)));
    v = f_.def_var("DEPLOYMENT_TIME", NC_DOUBLE, {});
    f_.put_att(v, "long_name", "date of deployment");
    f_.put_att(v, "standard_name", "time");
    f_.put_att(v, "calendar", "gregorian");
    f_.put_att(v, "units", "seconds since 1970-01-01T00:00:00Z");
    scalar_doubles_.emplace_back(v, m_.deployment_time_s);
    v = f_.def_var("DEPLOYMENT_LATITUDE", NC_DOUBLE, {});
    f_.put_att(v, "long_name", "latitude of deployment");
    f_.put_att(v, "units", "degrees_north");
    scalar_doubles_.emplace_back(v, m_.deployment_latitude);
    v = f_.def_var("DEPLOYMENT_LONGITUDE", NC_DOUBLE, {});
    f_.put_att(v, "long_name", "longitude of deployment");
    f_.put_att(v, "units", "degrees_east");
    scalar_doubles_.emplace_back(v, m_.deployment_longitude);
    v = string_scalar(sensor_name(), "", m_.ctd_model);
    f_.put_att(v, "sensor_type_vocabulary", "https://vocab.nerc.ac.uk/collection/L05/current/130/");
    f_.put_att(v, "sensor_model", m_.ctd_model);
    f_.put_att(
        v, "sensor_model_vocabulary",
        m_.ctd_model_vocabulary.empty() ? "https://vocab.nerc.ac.uk/collection/L22/current/" : m_.ctd_model_vocabulary);
    if (!m_.ctd_maker.empty()) f_.put_att(v, "sensor_maker", m_.ctd_maker);
    f_.put_att(v, "sensor_serial_number", m_.ctd_serial);
    if (!m_.ctd_calibration_date.empty()) f_.put_att(v, "sensor_calibration_date", m_.ctd_calibration_date);
  }

  static inline const DeploymentMetadata kNoMetadata{};
  DatasetSink& f_;
  const WriteContext& c_;
  const Trajectory& t_;
  const DeploymentMetadata& m_;  // kNoMetadata when none was given
  bool has_metadata_;
  int dim_ = -1;
  std::size_t chunk_ = 1;
  std::vector<std::pair<int, std::vector<double>>> doubles_;
  std::vector<std::pair<int, std::vector<std::int8_t>>> bytes_;
  std::vector<std::pair<int, std::vector<std::int32_t>>> ints_;
  std::vector<std::pair<int, std::string>> strings_;
  std::vector<std::pair<int, double>> scalar_doubles_;
  std::vector<std::pair<int, int>> scalar_ints_;
};

}  // namespace

std::string og1_id(const DeploymentMetadata& m) {
  return m.platform_serial + "_" + format_utc_compact(m.deployment_time_s) + "_" + m.data_mode;
}

void write_og1(const std::filesystem::path& path, const WriteContext& context) {
  if (context.metadata == nullptr) throw std::invalid_argument(path.string() + ": an OG1.0 file needs the metadata");
  NcFile file = NcFile::create(path, NcFile::Kind::kNetcdf4);
  Og1Writer(file, context).write();
  file.close();
}

MemoryDataset og1_dataset(const WriteContext& context) {
  MemoryDataset dataset;
  Og1Writer(dataset, context).write();
  return dataset;
}

}  // namespace glider::netcdf
