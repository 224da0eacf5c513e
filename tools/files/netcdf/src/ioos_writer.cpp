// SPDX-License-Identifier: Apache-2.0
// IOOS NGDAC NetCDF v2 (IOOS_Glider_NetCDF_v2.0.nc; ioos/glider-dac
// _docs/NGDAC-NetCDF-File-Format-Version-2.md): one file per profile, the
// time series of the profile's samples, the dimensionless profile_* and
// depth-averaged current (time_uv, lat_uv, lon_uv, u, v) variables, the
// platform and instrument_ctd containers, a _qc variable for each.
#include <netcdf.h>

#include <cmath>
#include <cstdio>

#include "glider/netcdf/writers.hpp"
#include "variable_writer.hpp"

namespace glider::netcdf {
namespace {

constexpr double kFill = -999.0;
const char* const kFlagMeanings =
    "no_qc_performed good_data probably_good_data bad_data_that_are_potentially_correctable bad_data value_changed "
    "not_used not_used interpolated_value missing_value";
const char* const kUvComment =
    "The depth-averaged current is an estimate of the net current measured while the glider is underwater. The value "
    "is calculated over the entire underwater segment, which may consist of 1 or more dives.";

struct Profile {
  std::size_t first = 0, last = 0;
  int id = 0;
};

class IoosWriter {
 public:
  IoosWriter(NcFile& file, const WriteContext& context, const Profile& profile)
      : f_(file), c_(context), t_(*context.trajectory), m_(*context.metadata), p_(profile) {}

  void write() {
    time_ = f_.def_dim("time", 0);
    const std::string name = trajectory_name();
    strlen_ = f_.def_dim("traj_strlen", name.size());
    globals();
    const int traj = f_.def_var("trajectory", NC_CHAR, {strlen_});
    f_.put_att(traj, "cf_role", "trajectory_id");
    f_.put_att(traj, "comment", "A trajectory is a single deployment of a glider and may span multiple data files.");
    f_.put_att(traj, "long_name", "Trajectory/Deployment Name");
    time_series();
    profile_scalars();
    containers();
    f_.end_define();
    f_.put_chars(traj, name);
    for (const auto& [var, values] : doubles_) f_.put(var, values);
    for (const auto& [var, values] : bytes_) f_.put(var, values);
    for (const auto& [var, value] : scalars_) f_.put_scalar(var, value);
    for (const auto& [var, value] : scalar_ints_) f_.put_scalar_int(var, value);
  }

  std::string trajectory_name() const {
    char stamp[32];
    const std::string compact = format_utc_compact(m_.deployment_time_s);
    std::snprintf(stamp, sizeof stamp, "%.13s", compact.c_str());  // YYYYmmddTHHMM
    return m_.platform_name + "-" + stamp;
  }

 private:
  void qc(int var_of, const std::string& name, const char* standard_name, std::vector<std::int8_t> flags, bool series) {
    const int v = f_.def_var(name + "_qc", NC_BYTE, series ? std::vector<int>{time_} : std::vector<int>{});
    f_.put_att(v, "_FillValue", NC_BYTE, {-127});
    f_.put_att(v, "flag_meanings", kFlagMeanings);
    f_.put_att(v, "flag_values", NC_BYTE, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
    f_.put_att(v, "long_name", name + " Quality Flag");
    f_.put_att(v, "standard_name", std::string(standard_name) + " status_flag");
    f_.put_att(v, "valid_max", NC_BYTE, {9});
    f_.put_att(v, "valid_min", NC_BYTE, {0});
    bytes_.emplace_back(v, std::move(flags));
    (void)var_of;
  }

  void globals() {
    // IOOS caveat 1: every listed attribute is required; " " where there is no meaningful value.
    auto g = [&](const char* name, const std::string& value) { f_.put_att(-1, name, value.empty() ? " " : value); };
    const std::string now = format_utc_iso(c_.created_s);
    g("Conventions", "CF-1.6");
    g("Metadata_Conventions", "CF-1.6, Unidata Dataset Discovery v1.0");
    g("acknowledgment", "");
    g("comment", "converted from Slocum binary files by glider-convert (this project)");
    g("contributor_name", m_.pi_name);
    g("contributor_role", m_.pi_role);
    g("creator_email", m_.pi_email);
    g("creator_name", m_.pi_name);
    g("creator_url", "");
    g("date_created", now);
    g("date_issued", now);
    g("date_modified", now);
    g("format_version", "IOOS_Glider_NetCDF_v2.0.nc");
    g("history", now + ": " + c_.history);
    g("id", trajectory_name());
    g("institution", m_.institution);
    g("keywords",
      "AUVS > Autonomous Underwater Vehicles, Oceans > Ocean Pressure > Water Pressure, Oceans > Ocean "
      "Temperature > Water Temperature, Oceans > Salinity/Density > Conductivity, Oceans > "
      "Salinity/Density > Density, Oceans > Salinity/Density > Salinity");
    g("keywords_vocabulary", "GCMD Science Keywords");
    g("license", m_.license);
    g("metadata_link", "");
    g("naming_authority", m_.naming_authority);
    g("platform_type", "Slocum Glider");
    g("processing_level",
      "Data provided as is with no expressed or implied assurance of quality assurance or "
      "quality control.");
    g("project", m_.project);
    g("publisher_email", m_.pi_email);
    g("publisher_name", m_.pi_name);
    g("publisher_url", "");
    g("references", "");
    g("sea_name", "");
    g("source", "Observational data from a profiling glider.");
    g("standard_name_vocabulary", "CF-v25");
    g("summary", m_.summary);
    g("title", trajectory_name());
    g("wmo_id", m_.wmo_id);
  }

  int series(const std::string& name, const std::vector<double>& all, const char* standard_name, const char* units,
             const char* long_name, const char* observation_type, double min, double max, bool instrument) {
    const std::vector<double> values = slice(all, p_.first, p_.last);
    const int v = f_.def_var(name, NC_DOUBLE, {time_});
    if (name != "time") f_.put_att(v, "_FillValue", kFill);
    f_.put_att(v, "ancillary_variables", name + "_qc");
    if (instrument) f_.put_att(v, "instrument", "instrument_ctd");
    f_.put_att(v, "long_name", long_name);
    f_.put_att(v, "observation_type", observation_type);
    f_.put_att(v, "platform", "platform");
    f_.put_att(v, "standard_name", standard_name);
    f_.put_att(v, "units", units);
    if (name != "time") {
      f_.put_att(v, "valid_max", max);
      f_.put_att(v, "valid_min", min);
    }
    if (instrument) {
      for (const char* a : {"accuracy", "precision", "resolution"}) f_.put_att(v, a, " ");
    }
    doubles_.emplace_back(v, with_fill(values, kFill));
    qc(v, name, standard_name, qc_flags(values, 0, 9), true);
    return v;
  }

  void time_series() {
    int v = series("time", t_.time_s, "time", "seconds since 1970-01-01T00:00:00Z", "Time", "measured", 0, 0, false);
    f_.put_att(v, "calendar", "gregorian");
    for (const char* name : {"lat", "lon"}) {
      const bool lat = name[1] == 'a';
      v = series(name, lat ? t_.latitude : t_.longitude, lat ? "latitude" : "longitude",
                 lat ? "degrees_north" : "degrees_east", lat ? "Latitude" : "Longitude", "measured",
                 lat ? -90.0 : -180.0, lat ? 90.0 : 180.0, false);
      f_.put_att(v, "comment", "Values may be interpolated between measured GPS fixes");
      f_.put_att(v, "coordinate_reference_frame", "urn:ogc:crs:EPSG::4326");
      f_.put_att(v, "reference", "WGS84");
    }
    v = series("pressure", t_.pressure_dbar, "sea_water_pressure", "dbar", "Pressure", "measured", 0, 2000, true);
    f_.put_att(v, "positive", "down");
    f_.put_att(v, "reference_datum", "sea-surface");
    f_.put_att(v, "comment", "sci_water_pressure (bar) x 10");
    v = series("depth", t_.depth_m, "depth", "m", "Depth", "calculated", 0, 2000, true);
    f_.put_att(v, "positive", "down");
    f_.put_att(v, "reference_datum", "sea-surface");
    f_.put_att(v, "comment", t_.depth_source);
    series("temperature", t_.temperature_c, "sea_water_temperature", "Celsius", "Temperature", "measured", -5, 40,
           true);
    series("conductivity", t_.conductivity_s_m, "sea_water_electrical_conductivity", "S m-1", "Conductivity",
           "measured", 0, 10, true);
    series("salinity", t_.salinity, "sea_water_practical_salinity", "1e-3", "Salinity", "calculated", 0, 40, true);
    series("density", t_.density_kg_m3, "sea_water_density", "kg m-3", "Density", "calculated", 1015, 1040, true);
  }

  int scalar(const std::string& name, double value, const char* standard_name, const char* units, const char* long_name,
             const char* comment) {
    const int v = f_.def_var(name, NC_DOUBLE, {});
    f_.put_att(v, "_FillValue", kFill);
    if (std::string(units).find("since") != std::string::npos) f_.put_att(v, "calendar", "gregorian");
    f_.put_att(v, "comment", comment);
    f_.put_att(v, "long_name", long_name);
    f_.put_att(v, "observation_type", "calculated");
    f_.put_att(v, "platform", "platform");
    f_.put_att(v, "standard_name", standard_name);
    f_.put_att(v, "units", units);
    if (std::string(standard_name) == "latitude") f_.put_att(v, "valid_max", 90.0), f_.put_att(v, "valid_min", -90.0);
    if (std::string(standard_name) == "longitude")
      f_.put_att(v, "valid_max", 180.0), f_.put_att(v, "valid_min", -180.0);
    if (std::string(units) == "m s-1") f_.put_att(v, "valid_max", 10.0), f_.put_att(v, "valid_min", -10.0);
    scalars_.emplace_back(v, std::isfinite(value) ? value : kFill);
    qc(v, name, standard_name, {static_cast<std::int8_t>(std::isfinite(value) ? 0 : 9)}, false);
    return v;
  }

  void profile_scalars() {
    const int id = f_.def_var("profile_id", NC_INT, {});
    f_.put_att(id, "_FillValue", NC_INT, {-999});
    f_.put_att(id, "comment",
               "Sequential profile number within the trajectory. This value is unique in each file that "
               "is part of a single trajectory/deployment.");
    f_.put_att(id, "long_name", "Profile ID");
    f_.put_att(id, "valid_max", NC_INT, {2147483647});
    f_.put_att(id, "valid_min", NC_INT, {1});
    scalar_ints_.emplace_back(id, p_.id);
    const std::size_t mid = p_.first + (p_.last - p_.first) / 2;
    const double mid_time = 0.5 * (t_.time_s[p_.first] + t_.time_s[p_.last]);
    scalar("profile_time", mid_time, "time", "seconds since 1970-01-01T00:00:00Z", "Profile Center Time",
           "Timestamp corresponding to the mid-point of the profile");
    scalar("profile_lat", t_.latitude[mid], "latitude", "degrees_north", "Profile Center Latitude",
           "Value is interpolated to provide an estimate of the latitude at the mid-point of the profile");
    scalar("profile_lon", t_.longitude[mid], "longitude", "degrees_east", "Profile Center Longitude",
           "Value is interpolated to provide an estimate of the longitude at the mid-point of the profile");
    const CurrentEstimate* uv = nullptr;
    if (c_.products != nullptr) {
      for (const CurrentEstimate& c : c_.products->currents) {
        if (c.first <= p_.first && p_.last <= c.last) uv = &c;
      }
    }
    const double nan = NAN;
    std::string uv_comment = kUvComment;
    if (c_.products == nullptr) uv_comment += " Not computed: no vehicle file was given (--vehicle).";
    scalar("time_uv", uv ? 0.5 * (uv->start_s + uv->end_s) : nan, "time", "seconds since 1970-01-01T00:00:00Z",
           "Depth-Averaged Time", uv_comment.c_str());
    scalar("lat_uv", uv ? uv->latitude : nan, "latitude", "degrees_north", "Depth-Averaged Latitude",
           uv_comment.c_str());
    scalar("lon_uv", uv ? uv->longitude : nan, "longitude", "degrees_east", "Depth-Averaged Longitude",
           uv_comment.c_str());
    int v = scalar("u", uv ? uv->east_m_s : nan, "eastward_sea_water_velocity", "m s-1",
                   "Depth-Averaged Eastward Sea Water Velocity", uv_comment.c_str());
    if (uv) f_.put_att(v, "uncertainty_m_s", uv->uncertainty_m_s);
    v = scalar("v", uv ? uv->north_m_s : nan, "northward_sea_water_velocity", "m s-1",
               "Depth-Averaged Northward Sea Water Velocity", uv_comment.c_str());
    if (uv) f_.put_att(v, "uncertainty_m_s", uv->uncertainty_m_s);
  }

  void containers() {
    int v = f_.def_var("platform", NC_INT, {});
    f_.put_att(v, "_FillValue", NC_INT, {-999});
    f_.put_att(v, "comment", m_.platform_model + " " + m_.platform_name);
    f_.put_att(v, "id", m_.platform_name);
    f_.put_att(v, "instrument", "instrument_ctd");
    f_.put_att(v, "long_name", m_.institution + " " + m_.platform_model + " " + m_.platform_name);
    f_.put_att(v, "type", "platform");
    f_.put_att(v, "wmo_id", m_.wmo_id.empty() ? " " : m_.wmo_id);
    scalar_ints_.emplace_back(v, -999);
    v = f_.def_var("instrument_ctd", NC_INT, {});
    f_.put_att(v, "_FillValue", NC_INT, {-999});
    f_.put_att(v, "calibration_date", m_.ctd_calibration_date.empty() ? " " : m_.ctd_calibration_date + "T00:00:00Z");
    f_.put_att(v, "calibration_report", " ");
    f_.put_att(v, "comment", m_.ctd_pumped ? "pumped CTD" : "unpumped CTD");
    f_.put_att(v, "factory_calibrated", " ");
    f_.put_att(v, "long_name", m_.ctd_model);
    f_.put_att(v, "make_model", (m_.ctd_maker.empty() ? "" : m_.ctd_maker + " ") + m_.ctd_model);
    f_.put_att(v, "platform", "platform");
    f_.put_att(v, "serial_number", m_.ctd_serial);
    f_.put_att(v, "type", "platform");
    scalar_ints_.emplace_back(v, -999);
  }

  NcFile& f_;
  const WriteContext& c_;
  const Trajectory& t_;
  const DeploymentMetadata& m_;
  Profile p_;
  int time_ = -1, strlen_ = -1;
  std::vector<std::pair<int, std::vector<double>>> doubles_;
  std::vector<std::pair<int, std::vector<std::int8_t>>> bytes_;
  std::vector<std::pair<int, double>> scalars_;
  std::vector<std::pair<int, int>> scalar_ints_;
};

}  // namespace

std::vector<std::filesystem::path> write_ioos(const std::filesystem::path& directory, const WriteContext& context) {
  const Trajectory& t = *context.trajectory;
  std::vector<Profile> profiles;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t.profile[i] <= 0) continue;
    if (profiles.empty() || profiles.back().id != t.profile[i]) profiles.push_back({i, i, t.profile[i]});
    profiles.back().last = i;
  }
  std::vector<std::filesystem::path> written;
  if (profiles.empty()) return written;
  std::filesystem::create_directories(directory);
  const char* mode = context.metadata->data_mode == "R" ? "rt" : "delayed";
  for (const Profile& p : profiles) {
    const std::string name =
        context.metadata->platform_name + "_" + format_utc_compact(t.time_s[p.first]) + "Z_" + mode + ".nc";
    const std::filesystem::path path = directory / name;
    NcFile file = NcFile::create(path, NcFile::Kind::kClassic);
    IoosWriter(file, context, p).write();
    file.close();
    written.push_back(path);
  }
  return written;
}

}  // namespace glider::netcdf
