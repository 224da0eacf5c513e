// SPDX-License-Identifier: Apache-2.0
#include "og1_xarray.hpp"

#include <netcdf.h>
#include <pybind11/stl.h>

#include <cstdlib>
#include <ctime>
#include <optional>
#include <string>

#include "glider/model/vehicle_file.hpp"
#include "glider/netcdf/deployment_metadata.hpp"
#include "glider/netcdf/flight_products.hpp"
#include "glider/netcdf/trajectory.hpp"
#include "glider/netcdf/writers.hpp"

namespace py = pybind11;

namespace glider::python {
namespace {

// An optional Python library: its ImportError says how to get it on Debian.
py::module_ import_optional(const char* module, const char* debian_package, const char* needed_by) {
  try {
    return py::module_::import(module);
  } catch (const py::error_already_set& e) {
    if (!e.matches(PyExc_ImportError)) throw;
    const std::string text = std::string(needed_by) + " needs the Python library " + module +
                             ", which is not installed: on Debian, apt-get install " + debian_package;
    PyErr_SetString(PyExc_ImportError, text.c_str());
    throw py::error_already_set();
  }
}

const char* numpy_dtype(int nc_type) {
  switch (nc_type) {
    case NC_BYTE:
      return "int8";
    case NC_UBYTE:
      return "uint8";
    case NC_SHORT:
      return "int16";
    case NC_INT:
      return "int32";
    case NC_FLOAT:
      return "float32";
    case NC_DOUBLE:
      return "float64";
    default:
      throw std::logic_error("no numpy type for NetCDF type " + std::to_string(nc_type));
  }
}

// An attribute as the netCDF4 library hands it to xarray: text as str, one
// number as a numpy scalar of its type, several as a numpy array.
py::object attribute_value(const netcdf::MemoryAttribute& a, const py::module_& np) {
  if (a.nc_type == NC_CHAR) return py::str(a.text);
  py::object values = np.attr("array")(a.values, py::arg("dtype") = numpy_dtype(a.nc_type));
  return a.values.size() == 1 ? values[py::int_(0)] : values;
}

py::dict attributes(const std::vector<netcdf::MemoryAttribute>& list, const py::module_& np) {
  py::dict out;
  for (const auto& a : list) out[py::str(a.name)] = attribute_value(a, np);
  return out;
}

// The dataset as its file would hold it, then decoded by xarray's own CF
// decoding (fill values -> NaN, TIME -> datetime64, coordinates), which is
// what xarray.open_dataset does to the file.
py::object to_xarray(const netcdf::MemoryDataset& d) {
  const py::module_ xr = import_optional("xarray", "python3-xarray", "the OG1.0 Dataset");
  const py::module_ np = py::module_::import("numpy");
  py::dict variables;
  for (const auto& v : d.variables) {
    py::tuple dims(v.dims.size());
    for (std::size_t i = 0; i < v.dims.size(); ++i)
      dims[i] = py::str(d.dimensions[static_cast<std::size_t>(v.dims[i])].name);
    py::object data;
    if (v.nc_type == NC_STRING) {
      data = np.attr("array")(py::str(v.text), py::arg("dtype") = "object");
    } else {
      data = np.attr("array")(v.values, py::arg("dtype") = numpy_dtype(v.nc_type));
      if (v.dims.empty()) data = data.attr("reshape")(py::tuple());
    }
    variables[py::str(v.name)] = xr.attr("Variable")(dims, data, attributes(v.attributes, np));
  }
  py::object raw = xr.attr("Dataset")(variables, py::arg("attrs") = attributes(d.globals, np));
  return xr.attr("decode_cf")(raw);
}

std::string path_of(const py::object& value) {
  return py::str(py::module_::import("os").attr("fspath")(value)).cast<std::string>();
}

// date_created as glider-convert writes it: now, or SOURCE_DATE_EPOCH.
double creation_time() {
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) return std::strtod(epoch, nullptr);
  return static_cast<double>(std::time(nullptr));
}

py::object og1_dataset(const Log& log, const py::object& metadata, const py::object& vehicle) {
  std::optional<netcdf::DeploymentMetadata> deployment;
  if (!metadata.is_none()) deployment = netcdf::load_deployment_metadata(path_of(metadata));
  std::optional<model::VehicleParams> params;
  if (!vehicle.is_none()) {
    params = py::isinstance<model::VehicleParams>(vehicle) ? vehicle.cast<model::VehicleParams>()
                                                           : model::load_vehicle_file(path_of(vehicle));
  }
  netcdf::MemoryDataset dataset;
  {
    py::gil_scoped_release release;
    const netcdf::Trajectory trajectory = netcdf::make_trajectory(log.log);
    std::optional<netcdf::FlightProducts> products;
    if (params) products = netcdf::compute_flight_products(trajectory, *params);
    netcdf::WriteContext context;
    context.trajectory = &trajectory;
    context.metadata = deployment ? &*deployment : nullptr;
    context.products = products ? &*products : nullptr;
    context.created_s = creation_time();
    context.history = "glider.to_og1_dataset (Python) of " + log.log.source();
    dataset = netcdf::og1_dataset(context);
  }
  return to_xarray(dataset);
}

py::object read_og1(const py::object& path) {
  const py::module_ xr = import_optional("xarray", "python3-xarray", "glider.read_og1");
  import_optional("netCDF4", "python3-netcdf4", "glider.read_og1 (xarray's NetCDF-4 engine)");
  py::object dataset = xr.attr("open_dataset")(path_of(path), py::arg("engine") = "netcdf4");
  py::object loaded = dataset.attr("load")();  // the values in memory: the file is closed on return
  dataset.attr("close")();
  return loaded;
}

py::object to_pandas(const Log& log) {
  const py::module_ pd = import_optional("pandas", "python3-pandas", "Log.to_pandas");
  py::dict columns;
  for (const auto& name : log.log.column_names()) columns[py::str(name)] = to_array(log.log.column(name));
  py::object index = pd.attr("to_datetime")(to_array(log.log.time()), py::arg("unit") = "s");
  index.attr("name") = "time";
  return pd.attr("DataFrame")(columns, py::arg("index") = index);
}

}  // namespace

void bind_og1(py::module_& m, py::class_<Log>& log_class) {
  const char* og1_doc =
      "The log as an xarray Dataset in the OG1.0 layout: the variables, attributes and units glider-convert "
      "--format og1 writes (the same writer), decoded as xarray.open_dataset decodes the file. metadata: the "
      "deployment metadata TOML (docs/netcdf.md; without it the platform, deployment and sensor elements are left "
      "out); vehicle: a vehicle file or Vehicle for the flight-model products.";
  log_class.def("to_xarray", &og1_dataset, py::arg("metadata") = py::none(), py::arg("vehicle") = py::none(), og1_doc);
  log_class.def("to_pandas", &to_pandas,
                "The log's columns as a pandas DataFrame (float64, NaN = no value that cycle), indexed by the log's "
                "time as datetime64 (UTC)");
  m.def("to_og1_dataset", &og1_dataset, py::arg("log"), py::arg("metadata") = py::none(),
        py::arg("vehicle") = py::none(), og1_doc);
  m.def("read_og1", &read_og1, py::arg("path"),
        "An OG1.0 (or any NetCDF) file as an xarray Dataset, read by xarray's netCDF4 engine and loaded into memory");
}

}  // namespace glider::python
