// SPDX-License-Identifier: Apache-2.0
#include "netcdf_output.hpp"

#include <cstdio>
#include <cstdlib>
#include <ctime>

#include "glider/cli/tool.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/netcdf/deployment_metadata.hpp"
#include "glider/netcdf/flight_products.hpp"
#include "glider/netcdf/writers.hpp"

namespace glider::convert {

namespace {
// date_created: now, or SOURCE_DATE_EPOCH (reproducible output, as the tests' golden header needs).
double creation_time() {
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) return std::strtod(epoch, nullptr);
  return static_cast<double>(std::time(nullptr));
}
}  // namespace

int write_netcdf(const slocum::Deployment& deployment, const NetcdfRequest& request, const std::string& out) {
  const netcdf::DeploymentMetadata metadata = netcdf::load_deployment_metadata(request.metadata);
  const netcdf::Trajectory trajectory = netcdf::make_trajectory(deployment.log);
  std::optional<netcdf::FlightProducts> products;
  if (!request.vehicle.empty()) {
    products = netcdf::compute_flight_products(trajectory, model::load_vehicle_file(request.vehicle));
  }
  netcdf::WriteContext context;
  context.trajectory = &trajectory;
  context.metadata = &metadata;
  context.products = products ? &*products : nullptr;
  context.created_s = creation_time();
  context.history = request.command_line;
  if (trajectory.profiles == 0) {
    std::fprintf(stderr, "warning: %s: no dive or climb of 3 m or more: no profiles\n", out.c_str());
  }
  if (request.format == "og1") {
    netcdf::write_og1(out, context);
    std::fprintf(stderr, "%s: OG1.0, %zu measurements, %zu profiles%s\n", out.c_str(), trajectory.size(),
                 trajectory.profiles, products ? ", flight-model products" : "");
    return cli::kOk;
  }
  if (trajectory.profiles == 0) {
    throw std::runtime_error(out + ": IOOS NGDAC files are one per profile and the data has none: nothing to write");
  }
  const auto files = netcdf::write_ioos(out, context);
  std::fprintf(stderr, "%s: IOOS NGDAC v2, %zu profile files%s\n", out.c_str(), files.size(),
               products ? ", depth-averaged currents from the flight model" : "");
  return cli::kOk;
}

}  // namespace glider::convert
