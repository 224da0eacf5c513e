// SPDX-License-Identifier: Apache-2.0
#pragma once
// A Log as an xarray Dataset in the OG1.0 layout (the OG1 writer's own
// variables and attributes, through netcdf::og1_dataset), as a pandas
// DataFrame, and OG1.0 files opened with xarray (docs/python.md). xarray,
// pandas and netCDF4 are optional: a missing one is an ImportError naming
// its Debian package.
#include <pybind11/pybind11.h>

#include "python_log.hpp"

namespace glider::python {

void bind_og1(pybind11::module_& m, pybind11::class_<Log>& log_class);

}  // namespace glider::python
