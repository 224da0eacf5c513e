// SPDX-License-Identifier: Apache-2.0
// glider-diagnose-deployment: a deployment made of many logs (segments)
// diagnosed as a whole; each effect the segments keep finding reported as a
// function of time (constant, linear trend or one step) with intervals.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "deployment_output.hpp"
#include "glider/cli/tool.hpp"
#include "glider/diagnose/deployment_diagnosis.hpp"
#include "glider/diagnose/tool_inputs.hpp"
#include "glider/slocum/binary_file.hpp"
#include "glider/slocum/deployment.hpp"
#include "glider/slocum/log_loader.hpp"

namespace {

namespace fs = std::filesystem;
using glider::diagnose::SegmentInput;

constexpr double kSecondsPerDay = 86400.0;
// Times before 1973 are not clock times: the log counts from its start (SIL).
constexpr double kEarliestClockTime_s = 1e8;

struct SegmentFiles {
  std::string name;
  std::vector<std::string> inputs;  // one CSV, or a segment's binary files
};

bool is_csv(const std::string& input) {
  std::string ext = fs::path(input).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".csv";
}

// A CSV is a segment; binary files are grouped by segment (the file name
// without its extension: a .dbd with its .ebd), `join` segments at a time.
std::vector<SegmentFiles> segment_files(const std::vector<std::string>& inputs, std::size_t join) {
  std::vector<SegmentFiles> segments;
  for (const std::string& input : inputs) {
    if (is_csv(input)) {
      segments.push_back({fs::path(input).stem().string(), {input}});
      continue;
    }
    std::size_t in_group = 0;
    std::string last_stem;
    for (const fs::path& file : glider::slocum::deployment_files({input})) {
      const std::string stem = file.stem().string();
      if (stem != last_stem) {
        if (in_group % join == 0)
          segments.push_back({stem, {}});
        else
          segments.back().name += "+" + stem;
        ++in_group;
        last_stem = stem;
      }
      segments.back().inputs.push_back(file.string());
    }
  }
  return segments;
}

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-diagnose-deployment",
                         "Diagnose a deployment of many logs: each effect over time (constant, trend or step)");
  CLI::App& app = tool.app();
  std::vector<std::string> inputs, renames, fit;
  std::vector<fs::path> cache_dirs;
  std::string vehicle_path, report_dir, flight_model = "dynamic";
  std::string default_vehicle;
  bool json = false;
  std::size_t join = 1;
  double days_apart = 0.0;
  app.add_option("LOGS", inputs,
                 "the segments: flight-log CSVs (one segment each), or a glider's binary files (files, directories, "
                 "globs: one segment per .dbd/.ebd pair)")
      ->required();
  app.add_option("--cache", cache_dirs, "sensor-list cache directory for binary files");
  app.add_option("--vehicle", vehicle_path,
                 "nominal vehicle file (else the first log's vehicle.* metadata, else --default-vehicle, else the "
                 "vehicle boards/gliders.toml gives for the glider the logs name)")
      ->check(CLI::ExistingFile);
  app.add_option("--default-vehicle", default_vehicle, "vehicle used when neither --vehicle nor metadata give one")
      ->check(CLI::ExistingFile);
  app.add_option("--model", flight_model, "flight model fitted in each segment: dynamic or steady")
      ->check(CLI::IsMember({"dynamic", "steady"}));
  app.add_option("--fit", fit, "fit exactly these effects in every segment (no selection pass)")->delimiter(',');
  tool.add_integer("--join", join, 1, 1000, "",
                   "binary files: this many consecutive segments make one (short segments)");
  tool.add_number("--days-apart", days_apart, {0.0, 1000.0, "days"},
                  "logs whose times count from their start (SIL logs) are placed this many days apart, in the "
                  "order given");
  app.add_option("--rename", renames, "read column FROM as TO (FROM=TO)");
  double drag_reynolds_exponent = glider::diagnose::kDragReynoldsExponentPrior;
  const CLI::Option* drag_reynolds_option =
      tool.add_number("--drag-reynolds-exponent", drag_reynolds_exponent, {0.0, 0.5, ""},
                      "glider-diagnose's skin-friction Reynolds exponent (as glider-diagnose: the vehicle file's if it "
                      "states one, else the prior 0.1; 0: off)");
  app.add_option("--report", report_dir, "write the summary, deployment.json and a plot per effect here");
  tool.add_json_flag(json);
  return tool.run(argc, argv, [&]() -> int {
    glider::diagnose::DeploymentOptions options;
    options.diagnose.model = flight_model == "steady" ? glider::diagnose::FlightModelKind::kSteady
                                                      : glider::diagnose::FlightModelKind::kDynamic;
    if (drag_reynolds_option->count() > 0) options.diagnose.drag_reynolds_exponent = drag_reynolds_exponent;
    glider::flightlog::ReadOptions read_options;
    try {
      options.effects = glider::diagnose::depth_rate_effects(fit);
      read_options.rename = glider::diagnose::column_renames(renames);
    } catch (const std::invalid_argument& error) {
      return tool.fail(glider::cli::kUsage, error.what());
    }

    std::vector<SegmentInput> segments;
    std::optional<glider::diagnose::NominalVehicle> vehicle;
    std::size_t relative = 0;
    for (const SegmentFiles& files : segment_files(inputs, join)) {
      SegmentInput& in = segments.emplace_back();
      in.name = files.name;
      try {
        std::vector<glider::slocum::Warning> warnings;
        const glider::flightlog::FlightLog log =
            glider::slocum::load_flight_log({files.inputs, cache_dirs}, read_options, &warnings);
        for (const auto& w : warnings) std::fprintf(stderr, "%s: warning: %s\n", tool.name().c_str(), w.text().c_str());
        if (!vehicle)
          vehicle = glider::diagnose::nominal_vehicle({vehicle_path, default_vehicle, glider::cli::boards_dir()}, log,
                                                      files.inputs.front());
        if (log.rows() > 0 && log.time().front() < kEarliestClockTime_s) {
          if (days_apart <= 0.0) {
            throw std::runtime_error("its times count from its start (" + std::to_string(log.time().front()) +
                                     " s), not a clock: give --days-apart D to place such logs in the deployment");
          }
          in.time_offset_s = static_cast<double>(relative++) * days_apart * kSecondsPerDay;
        }
        in.observations = glider::diagnose::prepare_observations(log);
      } catch (const glider::diagnose::NoVehicle&) {
        throw;
      } catch (const std::exception& error) {
        in.problem = error.what();
        std::fprintf(stderr, "%s: %s: not diagnosed: %s\n", tool.name().c_str(), in.name.c_str(), error.what());
      }
    }
    if (!vehicle) throw std::runtime_error("no segment could be read");
    options.progress = [&](int pass, std::size_t index, const std::string& name) {
      std::fprintf(stderr, "%s: %s segment %zu of %zu (%s)\n", tool.name().c_str(),
                   pass == 1 ? "diagnosing" : "fitting the deployment's effects in", index + 1, segments.size(),
                   name.c_str());
    };
    const glider::diagnose::DeploymentDiagnosis d = diagnose_deployment(vehicle->params, segments, options);
    if (d.diagnosed < 3) {
      glider::diagnose::print_deployment(d, vehicle->source);
      throw std::runtime_error("only " + std::to_string(d.diagnosed) +
                               " segment(s) could be diagnosed: a deployment needs at least 3 for a trend");
    }
    if (json) {
      std::printf("%s\n", glider::diagnose::deployment_json(d, vehicle->source).dump().c_str());
    } else {
      glider::diagnose::print_deployment(d, vehicle->source);
    }
    if (!report_dir.empty()) glider::diagnose::write_deployment_report(report_dir, d, vehicle->source);
    return static_cast<int>(glider::cli::kOk);
  });
}
