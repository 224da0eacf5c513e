// SPDX-License-Identifier: Apache-2.0
// `import glider`: the project's log reader, flight models and diagnosis for
// Python (docs/python.md). Everything runs in the same C++ libraries as the
// command-line tools, so a result here is the tools' result.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <dlfcn.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/diagnose/diagnose.hpp"
#include "glider/diagnose/diagnosis_json.hpp"
#include "glider/diagnose/dynamic_flight_model.hpp"
#include "glider/diagnose/flight_model.hpp"
#include "glider/diagnose/heading_report.hpp"
#include "glider/diagnose/observations.hpp"
#include "glider/diagnose/tool_inputs.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/slocum/log_loader.hpp"
#include "og1_xarray.hpp"
#include "python_log.hpp"

namespace py = pybind11;

namespace {

using glider::flightlog::FlightLog;
using glider::model::VehicleParams;

using glider::python::Log;
using glider::python::to_array;

std::vector<std::string> as_list(const py::object& value) {
  if (value.is_none()) return {};
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__")) {
    return {py::str(py::module_::import("os").attr("fspath")(value)).cast<std::string>()};
  }
  std::vector<std::string> out;
  for (const py::handle item : value) out.push_back(py::str(py::module_::import("os").attr("fspath")(item)));
  return out;
}

Log read_log(const py::object& inputs, const py::object& cache, const py::object& columns) {
  glider::slocum::LogSource source;
  source.inputs = as_list(inputs);
  for (const std::string& dir : as_list(cache)) source.cache_dirs.emplace_back(dir);
  glider::flightlog::ReadOptions options;
  options.required.clear();  // any log: the analyses check what they need
  options.columns = as_list(columns);
  std::vector<glider::slocum::Warning> warnings;
  Log out{glider::slocum::load_flight_log(source, options, &warnings), {}, source.inputs.front()};
  for (const auto& w : warnings) out.warnings.push_back(w.text());
  return out;
}

// The vehicle as glider-diagnose picks it (glider::diagnose::nominal_vehicle:
// the file given, else the log's vehicle.* metadata, else the vehicle
// boards/gliders.toml gives for the glider the log names; no silent default).
std::pair<VehicleParams, std::string> pick_vehicle(const Log& log, const py::object& vehicle) {
  if (!vehicle.is_none() && py::isinstance<VehicleParams>(vehicle)) {
    const auto& v = vehicle.cast<const VehicleParams&>();
    return {v, "vehicle " + v.name + " (given)"};
  }
  const std::string path = vehicle.is_none() ? std::string() : as_list(vehicle).front();
  auto picked = glider::diagnose::nominal_vehicle({path, "", glider::cli::boards_dir()}, log.log, log.first_input);
  return {std::move(picked.params), std::move(picked.source)};
}

glider::diagnose::FlightModelKind model_kind(const std::string& model) {
  if (model == "dynamic") return glider::diagnose::FlightModelKind::kDynamic;
  if (model == "steady") return glider::diagnose::FlightModelKind::kSteady;
  throw py::value_error("model must be 'dynamic' or 'steady', not '" + model + "'");
}

py::object diagnose(const Log& log, const py::object& vehicle, const std::string& model,
                    const std::optional<double>& drag_reynolds_exponent) {
  const auto [params, vehicle_source] = pick_vehicle(log, vehicle);
  glider::diagnose::DiagnoseOptions options;
  options.model = model_kind(model);
  // glider-diagnose's rule (its --drag-reynolds-exponent; unset, diagnose() chooses), so both give the same object.
  if (drag_reynolds_exponent && !(*drag_reynolds_exponent >= 0.0 && *drag_reynolds_exponent <= 0.5))
    throw py::value_error("drag_reynolds_exponent must be within [0, 0.5], not " +
                          std::to_string(*drag_reynolds_exponent));
  options.drag_reynolds_exponent = drag_reynolds_exponent;
  std::string text;
  {
    py::gil_scoped_release release;  // minutes on long logs: let other Python threads run
    const auto start = std::chrono::steady_clock::now();
    const auto observations = glider::diagnose::prepare_observations(log.log);
    const auto d = glider::diagnose::diagnose(params, observations, options);
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::ordered_json j = glider::diagnose::diagnosis_json(d, vehicle_source, wall_s);
    // As glider-diagnose's default --plane both: the heading plane on the vertical plane's findings.
    j["heading"] = glider::diagnose::heading_plane(glider::diagnose::heading_vehicle(params, d), log.log).json;
    text = j.dump();
  }
  return py::module_::import("json").attr("loads")(text);
}

// The nominal vehicle flown through the log: the time-domain (dynamic) or
// steady model's depth rate at each scored sample, with the measurement.
py::dict model_depth_rate(const Log& log, const py::object& vehicle, const std::string& model) {
  const VehicleParams params = pick_vehicle(log, vehicle).first;
  const auto obs = glider::diagnose::prepare_observations(log.log);
  std::vector<double> predicted;
  std::vector<std::size_t> samples;
  std::vector<double> time, depth, measured;
  if (model_kind(model) == glider::diagnose::FlightModelKind::kDynamic) {
    samples = obs.track.scored;
    glider::diagnose::DynamicFlightModel(params, obs.track)
        .predict(glider::diagnose::nominal_values(), false, samples, predicted);
    for (const std::size_t i : samples) {
      time.push_back(obs.track.time_s[i]);
      depth.push_back(obs.track.depth_m[i]);
      measured.push_back(obs.track.depth_rate_m_s[i]);
    }
  } else {
    for (std::size_t i = 0; i < obs.size(); ++i) samples.push_back(i);
    glider::diagnose::FlightModel(params, obs).predict(glider::diagnose::nominal_values(), false, samples, predicted);
    time = obs.time_s;
    depth = obs.depth_m;
    measured = obs.depth_rate_m_s;
  }
  py::dict out;
  out["time_s"] = to_array(time);
  out["depth_m"] = to_array(depth);
  out["measured_m_s"] = to_array(measured);
  out["model_m_s"] = to_array(predicted);
  return out;
}

py::dict steady_glide(const VehicleParams& vehicle, const py::array_t<double>& pitch_rad,
                      const py::array_t<double>& net_buoyancy_kg, double density_kg_m3) {
  const auto pitch = pitch_rad.unchecked<1>();
  const auto buoyancy = net_buoyancy_kg.unchecked<1>();
  if (pitch.shape(0) != buoyancy.shape(0)) throw py::value_error("pitch_rad and net_buoyancy_kg differ in length");
  const glider::model::PitchGlideSolver solver(vehicle.hydro);
  const auto n = static_cast<std::size_t>(pitch.shape(0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> speed(n, nan), depth_rate(n, nan), path(n, nan), alpha(n, nan), horizontal(n, nan);
  for (std::size_t i = 0; i < n; ++i) {
    const auto r =
        solver.solve(density_kg_m3, pitch(static_cast<py::ssize_t>(i)), buoyancy(static_cast<py::ssize_t>(i)));
    if (!r.glide) continue;
    speed[i] = r.glide->speed_m_s;
    depth_rate[i] = r.glide->depth_rate_m_s;
    path[i] = r.glide->glide_path_rad;
    alpha[i] = r.glide->alpha_rad;
    horizontal[i] = r.glide->horizontal_speed_m_s;
  }
  py::dict out;
  out["speed_m_s"] = to_array(speed);
  out["depth_rate_m_s"] = to_array(depth_rate);
  out["glide_path_rad"] = to_array(path);
  out["alpha_rad"] = to_array(alpha);
  out["horizontal_speed_m_s"] = to_array(horizontal);
  return out;
}

// A module installed by `pip install .` uses the boards/ (vehicles, gliders.toml)
// its wheel installed with it, in the installation's data directory
// (<data>/share/glider/boards), so that it does not depend on the source tree it
// was built from; GLIDER_BOARDS_DIR, when set, still decides (cli::boards_dir).
// Child processes (the glider-* tools run from Python) inherit it.
void use_installed_boards() {
  if (std::getenv("GLIDER_BOARDS_DIR") != nullptr) return;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&use_installed_boards), &info) == 0 || info.dli_fname == nullptr) return;
  const py::module_ sysconfig = py::module_::import("sysconfig");
  const std::filesystem::path platlib = sysconfig.attr("get_path")("platlib").cast<std::string>();
  std::error_code error;
  if (!std::filesystem::equivalent(std::filesystem::path(info.dli_fname).parent_path(), platlib, error)) return;
  const auto boards =
      std::filesystem::path(sysconfig.attr("get_path")("data").cast<std::string>()) / "share" / "glider" / "boards";
  if (std::filesystem::is_directory(boards / "vehicles", error)) {
    // Through os.environ, which sets the process's environment too: Python's view and the C++ one agree.
    py::module_::import("os").attr("environ")["GLIDER_BOARDS_DIR"] = boards.string();
  }
}

}  // namespace

PYBIND11_MODULE(glider, m) {
  use_installed_boards();
  m.doc() = "Underwater glider logs (CSV and Slocum binaries), flight models and diagnosis (docs/python.md)";

  py::class_<Log> log_class(m, "Log", "A flight log: one numpy array per column (NaN = no value that cycle)");
  log_class.def_property_readonly("source", [](const Log& l) { return l.log.source(); })
      .def_property_readonly("columns", [](const Log& l) { return l.log.column_names(); })
      .def_property_readonly("time", [](const Log& l) { return to_array(l.log.time()); })
      .def_property_readonly("metadata",
                             [](const Log& l) {
                               std::vector<std::pair<std::string, std::string>> out;
                               for (const auto& e : l.log.metadata()) out.emplace_back(e.key, e.value);
                               return out;
                             })
      .def_property_readonly("warnings", [](const Log& l) { return l.warnings; })
      .def("__len__", [](const Log& l) { return l.log.rows(); })
      .def("__contains__", [](const Log& l, const std::string& name) { return l.log.has(name); })
      .def("__getitem__",
           [](const Log& l, const std::string& name) {
             const auto* column = l.log.find(name);
             if (column == nullptr) throw py::key_error(name);
             return to_array(*column);
           })
      .def("to_dict", [](const Log& l) {
        py::dict out;
        for (const auto& name : l.log.column_names()) out[py::str(name)] = to_array(l.log.column(name));
        return out;
      });

  py::class_<VehicleParams>(m, "Vehicle", "A vehicle file (boards/vehicles/*.toml)")
      .def_readonly("name", &VehicleParams::name)
      .def_readonly("description", &VehicleParams::description);

  m.def("read_log", &read_log, py::arg("inputs"), py::arg("cache") = py::none(), py::arg("columns") = py::none(),
        "Read a flight-log CSV, an OG1.0 NetCDF file, or a glider's binary files (a directory, glob, file or list of "
        "them: .dbd .ebd ... and LZ4 .dcd .ecd ...; science files alone too), merged as glider-convert does. cache: "
        "sensor-list cache directory(ies).");
  m.def(
      "load_vehicle",
      [](const py::object& path) {
        return glider::model::load_vehicle_file(path.is_none() ? glider::cli::default_vehicle_path()
                                                               : as_list(path).front());
      },
      py::arg("path") = py::none(), "Load a vehicle file (default: the project's default vehicle)");
  m.def("steady_glide", &steady_glide, py::arg("vehicle"), py::arg("pitch_rad"), py::arg("net_buoyancy_kg"),
        py::arg("density_kg_m3") = 1025.0,
        "Steady glide at each pitch and net buoyancy (kg, + heavy): speed, depth rate, glide path, angle of attack "
        "(NaN where no glide exists)");
  m.def("model_depth_rate", &model_depth_rate, py::arg("log"), py::arg("vehicle") = py::none(),
        py::arg("model") = "dynamic",
        "The nominal vehicle flown through the log (dynamic: time-domain dynamics driven by the measured pitch; "
        "steady: steady glides): predicted and measured depth rate of the scored samples");
  m.def("diagnose", &diagnose, py::arg("log"), py::arg("vehicle") = py::none(), py::arg("model") = "dynamic",
        py::arg("drag_reynolds_exponent") = py::none(),
        "What the model gets wrong in the log: the same object as `glider-diagnose --json` (drag_reynolds_exponent: "
        "as its --drag-reynolds-exponent; None: the vehicle file's, else the prior)");
  glider::python::bind_og1(m, log_class);
}
