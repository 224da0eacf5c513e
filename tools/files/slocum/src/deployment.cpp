// SPDX-License-Identifier: Apache-2.0
// Merging a deployment's flight and science files into one flight log (the
// conventions are in deployment.hpp).
#include "glider/slocum/deployment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <unordered_map>
#include <unordered_set>

#include "glider/slocum/lat_lon.hpp"
#include "science_track.hpp"

namespace glider::slocum {
namespace {

namespace fs = std::filesystem;
constexpr double kEmpty = std::numeric_limits<double>::quiet_NaN();

bool is_science_name(std::string_view name) { return name.rfind("sci_", 0) == 0; }

// Name -> index of one sensor list, shared by the files that use that list.
class SensorIndex {
 public:
  std::optional<std::size_t> find(const BinaryFile& file, std::string_view name) {
    const auto& map = map_for(file);
    const auto it = map.find(std::string(name));
    if (it == map.end()) return std::nullopt;
    return it->second;
  }

 private:
  const std::unordered_map<std::string, std::size_t>& map_for(const BinaryFile& file) {
    auto& map = maps_[&file.sensors()];
    if (map.empty()) {
      for (std::size_t i = 0; i < file.sensors().size(); ++i) map.emplace(file.sensors()[i].name, i);
    }
    return map;
  }
  std::map<const SensorList*, std::unordered_map<std::string, std::size_t>> maps_;
};

// The rows: every kept cycle of the base files whose time is after the
// previous row's; row_of_cycle[file][cycle] is the row or -1.
struct Rows {
  std::vector<double> time;
  std::vector<std::vector<std::int64_t>> row_of_cycle;
};

Rows make_rows(const std::vector<BinaryFile>& base, bool skip_first, std::vector<Warning>& warnings) {
  Rows rows;
  double last = -std::numeric_limits<double>::infinity();
  for (const BinaryFile& file : base) {
    std::vector<std::int64_t>& map = rows.row_of_cycle.emplace_back(file.cycle_count(), -1);
    std::size_t dropped = 0;
    for (std::size_t c = skip_first ? 1 : 0; c < file.cycle_count(); ++c) {
      const double t = file.cycle_time()[c];
      if (!(t > last)) {
        ++dropped;
        continue;
      }
      map[c] = static_cast<std::int64_t>(rows.time.size());
      rows.time.push_back(t);
      last = t;
    }
    if (dropped > 0) {
      warnings.push_back({file.source(), 0,
                          std::to_string(dropped) + " cycles dropped: their " + file.time_variable() +
                              " is not after the previous row's (overlapping files, or time not set)"});
    }
  }
  return rows;
}

struct ColumnSpec {
  std::string name;
  bool from_science = false;  // interpolated from the science files onto flight time
  std::string unit;
  int bytes = 0;
};

// Per name: unit and size from the first file that has it with data, in file order.
struct Catalogue {
  std::vector<std::string> order;
  std::unordered_map<std::string, std::pair<std::string, int>> info;
  std::unordered_map<std::string, bool> has_data;
  void add(const std::vector<BinaryFile>& files) {
    for (const BinaryFile& file : files) {
      for (std::size_t i = 0; i < file.sensors().size(); ++i) {
        const Sensor& s = file.sensors()[i];
        const auto [it, added] = info.try_emplace(s.name, s.unit, s.bytes);
        if (added) order.push_back(s.name);
        if (!file.series()[i].cycles.empty()) has_data[s.name] = true;
      }
    }
  }
  bool has(const std::string& name) const { return info.count(name) != 0; }
};

void note_non_finite(std::map<std::string, std::size_t>& counts, const std::string& name) { ++counts[name]; }

// A column of the base files' own sensor: its value in each row's cycle.
flightlog::Column fill_direct(const std::string& name, const std::vector<BinaryFile>& base, const Rows& rows,
                              SensorIndex& index, std::map<std::string, std::size_t>& non_finite) {
  flightlog::Column column(rows.time.size(), kEmpty);
  const bool lat_lon = is_lat_lon_sensor(name);
  for (std::size_t f = 0; f < base.size(); ++f) {
    const auto i = index.find(base[f], name);
    if (!i) continue;
    const SensorSeries& series = base[f].series()[*i];
    const std::vector<std::int64_t>& row_of = rows.row_of_cycle[f];
    for (std::size_t k = 0; k < series.cycles.size(); ++k) {
      const std::int64_t row = row_of[series.cycles[k]];
      if (row < 0) continue;
      const double v = series.values[k];
      if (!std::isfinite(v)) {
        note_non_finite(non_finite, name);
        continue;
      }
      if (lat_lon && !is_valid_nmea(name, v)) continue;
      column[static_cast<std::size_t>(row)] = v;
    }
  }
  return column;
}

std::string describe_source(const std::vector<std::string>& files) {
  if (files.size() == 1) return files.front();
  const fs::path first(files.front());
  const fs::path last(files.back());
  return first.parent_path().string() + "/{" + first.filename().string() + " .. " + last.filename().string() + "} (" +
         std::to_string(files.size()) + " files)";
}

}  // namespace

Deployment read_deployment(const std::vector<fs::path>& paths, const DeploymentOptions& options) {
  std::vector<Warning> warnings;
  std::vector<Warning> sensor_warnings;  // kept only for the sensors that become columns
  std::vector<BinaryFile> flight;
  std::vector<BinaryFile> science;
  std::vector<std::string> read;
  SensorListMemo memo;
  ReadOptions read_options = options.read;
  if (read_options.memo == nullptr) read_options.memo = &memo;
  for (const fs::path& path : paths) {
    try {
      BinaryFile file = read_binary_file(path, read_options);
      for (const Warning& w : file.warnings()) (w.sensor.empty() ? warnings : sensor_warnings).push_back(w);
      read.push_back(path.string());
      (file.is_science() ? science : flight).push_back(std::move(file));
    } catch (const SlocumError& error) {
      warnings.push_back({error.file(), error.offset(),
                          std::string(error.what()).substr(Warning{error.file(), error.offset(), ""}.text().size()) +
                              " (file skipped, the rest of the set is read)"});
    }
  }
  if (flight.empty() && science.empty()) {
    std::string why;
    for (const Warning& w : warnings) why += "\n  " + w.text();
    throw SlocumError(paths.empty() ? std::string("(no files)") : paths.front().string(), 0,
                      "no file of the set could be read:" + why);
  }
  const bool science_only = flight.empty();
  const std::vector<BinaryFile>& base = science_only ? science : flight;
  const std::string time_name = science_only ? "sci_m_present_time" : "m_present_time";
  Rows rows = make_rows(base, read_options.skip_first_cycle, warnings);
  const std::string source = describe_source(read);
  if (rows.time.empty()) throw SlocumError(source, 0, "no data cycles with a time in the files");

  Catalogue base_sensors;
  base_sensors.add(base);
  Catalogue science_sensors;
  if (!science_only) science_sensors.add(science);

  // Which columns, from where.
  std::vector<ColumnSpec> specs;
  const auto spec_for = [&](const std::string& name) -> std::optional<ColumnSpec> {
    const bool science_wins = !science_only && !science.empty() && is_science_name(name) && science_sensors.has(name);
    if (science_wins) {
      const auto& [unit, bytes] = science_sensors.info.at(name);
      return ColumnSpec{name, true, unit, bytes};
    }
    if (base_sensors.has(name) && !(is_science_name(name) && !science.empty() && !science_only)) {
      const auto& [unit, bytes] = base_sensors.info.at(name);
      return ColumnSpec{name, false, unit, bytes};
    }
    if (science_sensors.has(name)) {
      const auto& [unit, bytes] = science_sensors.info.at(name);
      return ColumnSpec{name, true, unit, bytes};
    }
    return std::nullopt;
  };
  // Names already in specs (a set: every-sensor logs have ~1500 columns).
  std::unordered_set<std::string> chosen;
  const auto choose = [&](const ColumnSpec& spec) {
    chosen.insert(spec.name);
    specs.push_back(spec);
  };
  if (options.columns.empty()) {
    choose(*spec_for(time_name));
    for (const Catalogue* catalogue : {&base_sensors, &science_sensors}) {
      for (const std::string& name : catalogue->order) {
        if (name == time_name || !catalogue->has_data.count(name)) continue;
        const auto spec = spec_for(name);
        if (spec && (spec->from_science == (catalogue == &science_sensors)) && chosen.count(name) == 0) choose(*spec);
      }
    }
  } else {
    if (std::find(options.columns.begin(), options.columns.end(), time_name) == options.columns.end()) {
      choose(*spec_for(time_name));
    }
    for (const std::string& name : options.columns) {
      if (chosen.count(name) != 0) continue;
      const auto spec = spec_for(name);
      if (!spec && options.skip_missing_columns) continue;
      if (!spec) throw flightlog::FlightLogError(source, 0, name, 0, "no such sensor in the binary files");
      choose(*spec);
    }
  }

  // Fill.
  SensorIndex index;
  std::map<std::string, std::size_t> non_finite;
  std::vector<flightlog::Column> columns;
  columns.reserve(specs.size());
  const detail::ScienceTrack track(science, options.science_max_gap_s);
  std::size_t time_slot = 0;
  for (std::size_t c = 0; c < specs.size(); ++c) {
    const ColumnSpec& spec = specs[c];
    if (spec.name == time_name) {
      time_slot = c;
      columns.push_back(rows.time);
    } else if (spec.from_science) {
      columns.push_back(track.interpolate(spec.name, rows.time, non_finite));
    } else {
      columns.push_back(fill_direct(spec.name, base, rows, index, non_finite));
    }
  }
  // Non-finite values are left empty in the log; the reader's warnings say
  // where they are, for the columns the log has.
  for (Warning& w : sensor_warnings) {
    if (non_finite.count(w.sensor) == 0) continue;
    w.problem += ": left empty in the log";
    warnings.push_back(std::move(w));
  }

  std::vector<std::string> names;
  std::vector<std::string> units;
  std::vector<int> bytes;
  std::string unit_line;
  for (const ColumnSpec& spec : specs) {
    const auto renamed = std::find_if(options.rename.begin(), options.rename.end(),
                                      [&spec](const auto& r) { return r.first == spec.name; });
    names.push_back(renamed == options.rename.end() ? spec.name : renamed->second);
    units.push_back(spec.unit);
    bytes.push_back(spec.bytes);
    unit_line += (unit_line.empty() ? "" : ", ") + spec.name + " [" + spec.unit + "]";
  }
  std::vector<flightlog::MetadataEntry> metadata = {
      {"source", source},
      {"rows", science_only ? "one per science-computer cycle, time sci_m_present_time"
                            : "one per flight-computer cycle, time m_present_time; first (file-open) cycle of each "
                              "file dropped"},
      {"conventions",
       "dbd state codes: not-updated -> empty; same value -> that value; NMEA lat/lon, 69696969 -> "
       "empty; sci_* from the science files interpolated onto the flight time between samples < " +
           std::to_string(static_cast<int>(options.science_max_gap_s)) + " s apart"},
      {"units", unit_line}};
  // The binaries' own end marker stands for the CSV's end trailer: every
  // file read to its end (none skipped or cut) is a complete log.
  const bool all_complete =
      read.size() == paths.size() &&
      std::all_of(flight.begin(), flight.end(), [](const BinaryFile& f) { return f.complete(); }) &&
      std::all_of(science.begin(), science.end(), [](const BinaryFile& f) { return f.complete(); });
  Deployment out{flightlog::FlightLog(source, std::move(metadata), std::move(names), std::move(columns), time_slot),
                 std::move(units), std::move(bytes), std::move(read), std::move(warnings)};
  if (all_complete) {
    flightlog::LogEnd end;
    end.state = flightlog::LogEnd::State::kComplete;
    end.trailer_rows = out.log.rows();
    out.log.set_end(end);
  }
  return out;
}

}  // namespace glider::slocum
