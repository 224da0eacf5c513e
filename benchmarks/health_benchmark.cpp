// SPDX-License-Identifier: Apache-2.0
// Flight health measured (issue 24; docs/health.md): SIL deployments on
// decimated .sbd files with faults drawn at random each run (fresh seed
// unless --seed, printed), health updated one surfacing at a time through
// its state file as the shore runs it. Prints detection (alerted at one of
// the first 3 surfacings with the fault), size within 20 %, interval
// coverage, false alarms per 100 glider-days (clean SIL deployments, the
// fault draws' other effects, the real deployments of tests/data/real) and
// the cost of one surfacing's update. Not a CTest: run by
// `./glider benchmark health`.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/health/glider_dir.hpp"
#include "glider/health/health.hpp"
#include "sil_deployment.hpp"

namespace {

namespace fs = std::filesystem;
using namespace glider;
using health::HealthEffect;

constexpr double kHoursApart = 8.0;
constexpr double kPerDay = 24.0 / kHoursApart;

enum class Fault { kNone, kDrag, kBuoyancy, kFin, kPump };
const char* name(Fault f) {
  switch (f) {
    case Fault::kNone:
      return "clean";
    case Fault::kDrag:
      return "drag +2-5 %/day from day 2-8";
    case Fault::kBuoyancy:
      return "buoyancy step 30-80 g either way";
    case Fault::kFin:
      return "fin effectiveness halved";
    case Fault::kPump:
      return "pump rate -30 %";
  }
  return "";
}
// The --faults name of a kind.
std::string kind_name(Fault f) {
  switch (f) {
    case Fault::kDrag:
      return "drag";
    case Fault::kBuoyancy:
      return "buoyancy";
    case Fault::kFin:
      return "fin";
    case Fault::kPump:
      return "pump";
    default:
      return "clean";
  }
}
HealthEffect effect_of(Fault f) {
  switch (f) {
    case Fault::kDrag:
      return HealthEffect::kDragChange;
    case Fault::kBuoyancy:
      return HealthEffect::kBuoyancyOffset;
    case Fault::kFin:
      return HealthEffect::kFinEffectiveness;
    case Fault::kPump:
      return HealthEffect::kPumpRate;
    default:
      return HealthEffect::kCount;
  }
}

struct Draw {
  Fault fault = Fault::kNone;
  health_sil::FaultPlan plan;
  int surfacings = 0;
  int onset = -1;      // first surfacing flown with the fault
  double truth = 0.0;  // the size the alert should give (drag: rate/day; step: g; fin, pump: fraction)
  std::uint64_t seed = 0;
  std::string text;
};

struct Outcome {
  int detected = -1;  // surfacing of the first alert of the fault's effect (-1: never)
  bool sized = false, within_20 = false, covered = false;
  double size = 0.0, low = 0.0, high = 0.0;
  std::vector<std::string> false_alarms;  // other alerts (distinct ids), with the surfacing
  double glider_days = 0.0;
  int fin_not_judged = 0;  // segments whose fin turned too little to judge
  double min_fin_spread_deg = std::nan("");
  double min_heading_spread_deg = std::nan("");
  std::vector<double> update_s;  // wall time of each surfacing's update
  std::vector<double> update_cpu_s;
  std::string error;
};

Draw draw(Fault fault, std::mt19937_64& rng) {
  Draw d;
  d.fault = fault;
  d.seed = rng();
  std::uniform_real_distribution<double> u(0.0, 1.0);
  switch (fault) {
    case Fault::kNone:
      d.surfacings = 30;
      d.text = "clean, 10 days";
      break;
    case Fault::kDrag: {
      d.surfacings = 30;
      d.plan.drag_per_day = 0.02 + 0.03 * u(rng);
      d.plan.drag_onset_day = 2.0 + 6.0 * u(rng);
      // Surfacing k flies day k / kPerDay: the first with a larger drag.
      d.onset = static_cast<int>(std::floor(d.plan.drag_onset_day * kPerDay)) + 1;
      d.truth = d.plan.drag_per_day;
      char t[120];
      std::snprintf(t, sizeof t, "drag +%.2f %%/day from day %.2f (surfacing %d)", 100 * d.truth, d.plan.drag_onset_day,
                    d.onset);
      d.text = t;
      break;
    }
    default: {
      d.surfacings = 12;
      d.onset = 3 + static_cast<int>(rng() % 6);  // surfacings 3-8: at least 3 before and after
      char t[120];
      if (fault == Fault::kBuoyancy) {
        d.plan.step_g = (30.0 + 50.0 * u(rng)) * (rng() % 2 ? 1.0 : -1.0);
        d.plan.step_at = d.onset;
        d.truth = d.plan.step_g;
        std::snprintf(t, sizeof t, "buoyancy %+.1f g at surfacing %d", d.truth, d.onset);
      } else if (fault == Fault::kFin) {
        d.plan.fin_factor = 0.5;
        d.plan.fin_at = d.onset;
        d.truth = -0.5;
        std::snprintf(t, sizeof t, "fin effectiveness x0.5 at surfacing %d", d.onset);
      } else {
        d.plan.pump_factor = 0.7;
        d.plan.pump_at = d.onset;
        d.truth = -0.3;
        std::snprintf(t, sizeof t, "pump rate x0.7 at surfacing %d", d.onset);
      }
      d.text = t;
    }
  }
  return d;
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : ",") + w;
  return text;
}

// The disturbance options as given (empty: still water), for the replay line.
std::string disturbance_args(const health_sil::Disturbance& sea) {
  char t[160] = "";
  if (sea.yaw_deg_s > 0.0)
    std::snprintf(t, sizeof t, " --yaw-disturbance %g --yaw-correlation %g", sea.yaw_deg_s, sea.yaw_correlation_s);
  std::string text = t;
  if (sea.compass_noise_deg >= 0.0) {
    std::snprintf(t, sizeof t, " --compass-noise %g", sea.compass_noise_deg);
    text += t;
  }
  return text;
}

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

Outcome run(const Draw& d, const std::string& dir, int launch_spread_deg, const std::string& sbdlist) {
  Outcome o;
  fs::remove_all(dir);
  const health::HealthOptions options = health_sil::health_options(dir, kHoursApart);
  const HealthEffect target = effect_of(d.fault);
  std::set<std::string> other_ids;
  health::HealthRun last;
  fs::create_directories(dir);
  std::ofstream(dir + "/draw.txt") << kind_name(d.fault) << ' ' << d.onset << ' ' << d.truth << ' ' << d.surfacings
                                   << '\n';
  for (int k = 0; k < d.surfacings; ++k) {
    o.error = health_sil::fly_surfacing(dir + "/sbd", d.plan, k, kHoursApart, d.seed + static_cast<std::uint64_t>(k),
                                        sbdlist, launch_spread_deg);
    if (!o.error.empty()) return o;
    const double cpu0 = cpu_seconds();
    const auto wall0 = std::chrono::steady_clock::now();
    try {
      last = health::update_health(options);
    } catch (const std::exception& e) {
      o.error = e.what();
      return o;
    }
    o.update_s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count());
    o.update_cpu_s.push_back(cpu_seconds() - cpu0);
    for (const health::Alert& a : last.assessment.alerts) {
      const bool is_target = a.effect == target && d.onset >= 0 && k >= d.onset;
      if (is_target) {
        if (o.detected < 0) o.detected = k;
      } else if (other_ids.insert(std::string(health::info(a.effect).id) + "/" + a.kind).second) {
        o.false_alarms.push_back("surfacing " + std::to_string(k) + ": " + a.message);
      }
    }
  }
  o.glider_days = d.surfacings / kPerDay;
  for (const health::SegmentMeasurement& m : last.segments) {
    if (m.judged && !m.effects[static_cast<std::size_t>(HealthEffect::kFinEffectiveness)].judged()) ++o.fin_not_judged;
    if (std::isfinite(m.fin_spread_deg) && !(m.fin_spread_deg >= o.min_fin_spread_deg))
      o.min_fin_spread_deg = m.fin_spread_deg;
    if (std::isfinite(m.heading_spread_deg) && !(m.heading_spread_deg >= o.min_heading_spread_deg))
      o.min_heading_spread_deg = m.heading_spread_deg;
  }
  // The size at the last surfacing: the drag's rate from its line alert,
  // the others' step.
  for (const health::Alert& a : last.assessment.alerts) {
    if (a.effect != target) continue;
    if (d.fault == Fault::kDrag && a.kind != "line") continue;
    if (d.fault != Fault::kDrag && a.kind != "step") continue;
    o.sized = true;
    o.size = a.size;
    o.low = a.low;
    o.high = a.high;
  }
  if (o.sized) {
    o.within_20 = std::abs(o.size - d.truth) <= 0.2 * std::abs(d.truth);
    o.covered = o.low <= d.truth && d.truth <= o.high;
  }
  return o;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::min<double>(v.size() - 1, std::floor(p * static_cast<double>(v.size()))))];
}

// One clean deployment whose surfacings are drawn among the box launched
// anywhere, a straight transect (no turn at all) and a transect launched off
// its heading by 1-40 deg (one small turn): the fin judged only where the
// segment turned (docs/health.md, "The fin is judged only on segments that
// turn"; in disturbed water, "The fin in disturbed water"). Prints each
// segment's route, fin and heading spreads and fin reading; returns
// the fin alerts raised (a clean deployment: each one false) or -1.
int run_transects(std::uint64_t seed, const std::string& dir, int surfacings, const health_sil::Disturbance& sea,
                  const std::string& sbdlist) {
  fs::remove_all(dir);
  const health::HealthOptions options = health_sil::health_options(dir, kHoursApart);
  std::mt19937_64 rng(seed);
  std::set<std::string> fin_ids;
  int other_alerts = 0;
  std::vector<std::string> routes;
  health::HealthRun last;
  health_sil::FaultPlan plan;
  plan.disturbance = sea;
  for (int k = 0; k < surfacings; ++k) {
    const std::uint64_t s = rng();
    const int kind = static_cast<int>(rng() % 3);
    const int turn = kind == 1 ? 0 : static_cast<int>(1 + rng() % 40) * (rng() % 2 ? 1 : -1);
    std::string error;
    char route[64];
    if (kind == 0) {
      error = health_sil::fly_surfacing(dir + "/sbd", plan, k, kHoursApart, s, sbdlist, 180);
      std::snprintf(route, sizeof route, "box, launched %llu deg", static_cast<unsigned long long>(s % 361));
    } else {
      error = health_sil::fly_transect(dir + "/sbd", plan, k, kHoursApart, s, turn);
      std::snprintf(route, sizeof route, "transect, turn %+d deg", turn);
    }
    if (!error.empty()) {
      std::printf("    surfacing %d: ERROR %s\n", k, error.c_str());
      return -1;
    }
    routes.emplace_back(route);
    last = health::update_health(options);
    for (const health::Alert& a : last.assessment.alerts) {
      if (a.effect == HealthEffect::kFinEffectiveness) {
        if (fin_ids.insert(a.id).second) std::printf("    surfacing %d: FIN ALERT %s\n", k, a.message.c_str());
      } else {
        ++other_alerts;
      }
    }
  }
  for (const health::SegmentMeasurement& m : last.segments) {
    // The surfacing of a file <vehicle>-1970-000-<k>-<segment>.
    const std::string name = m.name.substr(0, m.name.rfind('-'));
    const auto k = static_cast<std::size_t>(std::stoi(name.substr(name.rfind('-') + 1)));
    const health::EffectValue& fin = m.effects[static_cast<std::size_t>(HealthEffect::kFinEffectiveness)];
    if (!m.judged) continue;
    std::printf("    %-26s %s fin spread %5.2f deg, heading spread %6.2f deg  ",
                k < routes.size() ? routes[k].c_str() : "?", m.name.substr(m.name.size() - 3).c_str(), m.fin_spread_deg,
                m.heading_spread_deg);
    if (fin.judged()) {
      std::printf("fin %.4f [%.4f, %.4f]\n", fin.value, fin.low, fin.high);
    } else {
      std::printf("not judged: %s\n", fin.why.c_str());
    }
  }
  const health::EffectAssessment& fin =
      last.assessment.effects[static_cast<std::size_t>(HealthEffect::kFinEffectiveness)];
  std::printf("    fin level %.4f [%.4f, %.4f]%s%s; fin alerts %zu, other alerts %d\n", fin.value, fin.low, fin.high,
              fin.judged ? "" : ", cannot judge: ", fin.judged ? "" : fin.why.c_str(), fin_ids.size(), other_alerts);
  return static_cast<int>(fin_ids.size());
}

// The surfacing k of a SIL segment named <vehicle>-1970-000-<k>-<segment>.
int surfacing_of(const std::string& segment_name) {
  const std::string name = segment_name.substr(0, segment_name.rfind('-'));
  return std::stoi(name.substr(name.rfind('-') + 1));
}

struct ReplayTally {
  std::size_t draws = 0, detected3 = 0, within = 0, covered = 0, others = 0;
  double days = 0.0;
};

// One saved deployment (DIR/drawN: its draw.txt and state.json) assessed
// again at every surfacing from the stored measurements (no flight, no fit):
// this build's alert rule on the same segments. Prints the faulted effect's
// assessment from the surfacing before its onset; returns false when the
// deployment is not there.
bool replay_draw(const fs::path& dir, std::map<std::string, ReplayTally>& tally) {
  std::ifstream meta(dir / "draw.txt");
  std::string kind;
  int onset = -1, surfacings = 0;
  double truth = 0.0;
  if (!(meta >> kind >> onset >> truth >> surfacings)) return false;
  std::string problem;
  const std::optional<health::HealthState> state = health::read_state((dir / "state.json").string(), problem);
  if (!state) {
    std::printf("  %s: no state (%s)\n", dir.string().c_str(), problem.c_str());
    return false;
  }
  Fault fault = Fault::kNone;
  for (Fault f : {Fault::kDrag, Fault::kBuoyancy, Fault::kFin, Fault::kPump}) {
    if (kind_name(f) == kind) fault = f;
  }
  const HealthEffect target = effect_of(fault);
  std::printf("  %s: %s, onset %d\n", dir.filename().string().c_str(), kind.c_str(), onset);
  std::vector<health::SegmentMeasurement> known;
  std::vector<health::Alert> previous;
  std::set<std::string> other_ids;
  int detected = -1;
  health::Assessment last;
  for (int k = 0; k < surfacings; ++k) {
    known.clear();
    for (const health::SegmentMeasurement& m : state->segments) {
      if (surfacing_of(m.name) <= k) known.push_back(m);
    }
    last = health::assess(known, previous);
    previous = last.alerts;
    for (const health::Alert& a : last.alerts) {
      if (a.effect == target && onset >= 0 && k >= onset) {
        if (detected < 0) detected = k;
      } else if (other_ids.insert(std::string(health::info(a.effect).id) + "/" + a.kind).second) {
        std::printf("      other at %d: %s\n", k, a.message.c_str());
      }
    }
    if (fault == Fault::kNone || k < onset - 1 || k > onset + 4) continue;
    const health::EffectAssessment& e = last.effects[static_cast<std::size_t>(target)];
    std::printf("    %2d (%+d) %-8s p_step %-9.3g level %.4f [%.4f, %.4f] %s", k, k - onset,
                diagnose::to_string(e.trend.shape), e.trend.p_step, e.value, e.low, e.high,
                e.judged ? "judged" : ("not judged: " + e.why).c_str());
    for (const health::Alert& a : e.alerts)
      std::printf("; ALERT %s %.4f [%.4f, %.4f]", a.kind.c_str(), a.size, a.low, a.high);
    std::printf("\n");
  }
  ReplayTally& t = tally[kind];
  ++t.draws;
  t.days += surfacings / kPerDay;
  t.others += other_ids.size();
  if (fault == Fault::kNone) return true;
  if (detected >= onset && detected <= onset + 2) ++t.detected3;
  for (const health::Alert& a : last.alerts) {
    if (a.effect != target || a.kind != (fault == Fault::kDrag ? "line" : "step")) continue;
    t.within += std::abs(a.size - truth) <= 0.2 * std::abs(truth) ? 1 : 0;
    t.covered += a.low <= truth && truth <= a.high ? 1 : 0;
  }
  std::printf("    alerted at %d (onset %d)\n", detected, onset);
  return true;
}

int replay(const std::string& root) {
  std::vector<std::pair<int, fs::path>> dirs;
  for (const auto& entry : fs::directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && name.rfind("draw", 0) == 0) dirs.emplace_back(std::stoi(name.substr(4)), entry.path());
  }
  std::sort(dirs.begin(), dirs.end());
  std::printf("bench_health --replay %s (the saved deployments' states, this build's alert rule)\n", root.c_str());
  std::map<std::string, ReplayTally> tally;
  for (const auto& [index, dir] : dirs) replay_draw(dir, tally);
  std::printf(
      "\n| fault | draws | alerted within 3 surfacings | size within 20 %% | interval covers truth | other alerts |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const auto& [kind, t] : tally) {
    std::printf("| %s | %zu | %zu | %zu | %zu | %zu in %.1f glider-days |\n", kind.c_str(), t.draws, t.detected3,
                t.within, t.covered, t.others, t.days);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  cli::Tool tool("bench_health", "Flight health on SIL deployments with drawn faults (fresh seeds)");
  CLI::App& app = tool.app();
  constexpr std::size_t kAsDraws = 1001;  // --clean not given
  std::size_t draws = 4, clean = kAsDraws;
  std::uint64_t seed = 0;
  int launch_spread_deg = health_sil::kDefaultLaunchSpreadDeg;
  std::string out = "build/release/benchmark/health";
  tool.add_integer("--draws", draws, 1, 1000, "", "deployments per fault kind");
  tool.add_integer("--clean", clean, 0, 1000, "", "clean 10-day deployments (default: as --draws; 0: none)");
  tool.add_integer("--seed", seed, 0, cli::kMaxSeed, "", "replay a run (default: a fresh seed, printed)");
  tool.add_integer("--launch-spread", launch_spread_deg, 0, 180, "deg",
                   "each surfacing starts heading 180 deg +- this (default 10: one long first turn, the box's "
                   "first leg being north; 180: any heading)");
  app.add_option("--out", out, "scratch folder for the deployments' files");
  std::size_t transects = 0;
  tool.add_integer("--transects", transects, 0, 1000, "",
                   "instead: this many clean 3-day deployments mixing the box, straight transects and transects "
                   "with one small turn (the fin on segments that turn too little)");
  health_sil::Disturbance sea;
  app.add_option("--yaw-disturbance", sea.yaw_deg_s,
                 "a random yaw rate of this RMS (deg/s) in every surfacing (default 0: still water; the comet "
                 "logs' calibration 0.34-0.82)")
      ->check(CLI::Range(0.0, 5.0));
  app.add_option("--yaw-correlation", sea.yaw_correlation_s, "its correlation time (s, default 4)")
      ->check(CLI::Range(0.1, 3600.0));
  app.add_option("--compass-noise", sea.compass_noise_deg, "the compass's white noise (deg; default: the SIL's 0.2)")
      ->check(CLI::Range(0.0, 20.0));
  std::string sbdlist_path;
  app.add_option("--sbdlist", sbdlist_path,
                 "the box's .sbd list (default tests/health/sbdlist.dat; a list without decimation keeps every "
                 "cycle: the decimation's part in a reading)")
      ->check(CLI::ExistingFile);
  std::string replay_dir;
  app.add_option("--replay", replay_dir,
                 "instead: assess the deployments saved in this --out folder again at every surfacing from their "
                 "states (no flight, no fit: this build's alert rule on the same segments)")
      ->check(CLI::ExistingDirectory);
  std::vector<std::string> kinds{"drag", "buoyancy", "fin", "pump"};
  app.add_option("--faults", kinds, "fault kinds drawn (default: all; a bounded run measures one)")
      ->delimiter(',')
      ->check(CLI::IsMember({"drag", "buoyancy", "fin", "pump"}));
  return tool.run(argc, argv, [&]() -> int {
    if (!replay_dir.empty()) return replay(replay_dir);
    if (seed == 0) seed = std::random_device{}() % 1000000000ULL + 1;
    if (clean == kAsDraws) clean = draws;
    std::string sbdlist;
    if (!sbdlist_path.empty()) {
      std::ifstream in(sbdlist_path);
      sbdlist.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    if (transects > 0) {
      std::printf("bench_health --seed %llu --transects %zu%s  (surfacings %g h apart, the box's .sbd: %s)\n",
                  static_cast<unsigned long long>(seed), transects, disturbance_args(sea).c_str(), kHoursApart,
                  sbdlist_path.empty() ? "tests/health/sbdlist.dat" : sbdlist_path.c_str());
      std::mt19937_64 rng(seed);
      int fin_alerts = 0, failed = 0;
      for (std::size_t i = 0; i < transects; ++i) {
        const std::uint64_t s = rng();
        std::printf("  deployment %zu (seed %llu):\n", i, static_cast<unsigned long long>(s));
        const int n = run_transects(s, out + "/transects" + std::to_string(i), 9, sea, sbdlist);
        if (n < 0) ++failed;
        fin_alerts += std::max(n, 0);
        std::fflush(stdout);
      }
      std::printf("\nfin alerts in %zu clean deployments (3 days each): %d (%d failed to fly)\n", transects, fin_alerts,
                  failed);
      return 0;
    }
    std::printf(
        "bench_health --seed %llu --draws %zu --clean %zu --faults %s --launch-spread %d%s  (surfacings %g h apart, "
        ".sbd: %s)\n",
        static_cast<unsigned long long>(seed), draws, clean, joined(kinds).c_str(), launch_spread_deg,
        disturbance_args(sea).c_str(), kHoursApart,
        sbdlist_path.empty() ? "tests/health/sbdlist.dat" : sbdlist_path.c_str());
    std::mt19937_64 rng(seed);
    std::vector<double> update_s, update_cpu_s;
    std::map<Fault, std::vector<std::pair<Draw, Outcome>>> results;
    std::vector<Fault> plan;
    for (std::size_t i = 0; i < draws; ++i) {
      for (Fault f : {Fault::kDrag, Fault::kBuoyancy, Fault::kFin, Fault::kPump}) {
        if (std::find(kinds.begin(), kinds.end(), kind_name(f)) != kinds.end()) plan.push_back(f);
      }
    }
    for (std::size_t i = 0; i < clean; ++i) plan.push_back(Fault::kNone);
    std::size_t n = 0;
    for (Fault f : plan) {
      Draw d = draw(f, rng);
      d.plan.disturbance = sea;
      const Outcome o = run(d, out + "/draw" + std::to_string(n++), launch_spread_deg, sbdlist);
      std::printf("  %-48s ", d.text.c_str());
      if (!o.error.empty()) {
        std::printf("ERROR: %s\n", o.error.c_str());
      } else {
        if (f != Fault::kNone) {
          std::printf("alerted at %d (onset %d)", o.detected, d.onset);
          if (o.sized) std::printf(", size %.4g [%.4g, %.4g] (truth %.4g)", o.size, o.low, o.high, d.truth);
        }
        std::printf(
            "; other alerts %zu; fin not judged on %d segments (smallest fin spread %.2f deg, heading spread %.1f "
            "deg)\n",
            o.false_alarms.size(), o.fin_not_judged, o.min_fin_spread_deg, o.min_heading_spread_deg);
        for (const std::string& fa : o.false_alarms) std::printf("      other: %s\n", fa.c_str());
        update_s.insert(update_s.end(), o.update_s.begin(), o.update_s.end());
        update_cpu_s.insert(update_cpu_s.end(), o.update_cpu_s.begin(), o.update_cpu_s.end());
      }
      std::fflush(stdout);
      results[f].push_back({d, o});
    }

    std::printf(
        "\n| fault | draws | alerted within 3 surfacings | size within 20 %% | interval covers truth | "
        "other alerts |\n|---|---|---|---|---|---|\n");
    double clean_days = 0.0, fault_days = 0.0;
    std::size_t clean_alarms = 0, fault_alarms = 0;
    for (auto& [f, list] : results) {
      std::size_t ok = 0, detected3 = 0, within = 0, covered = 0, others = 0;
      double days = 0.0;
      for (const auto& [d, o] : list) {
        if (!o.error.empty()) continue;
        ++ok;
        days += o.glider_days;
        others += o.false_alarms.size();
        if (f == Fault::kNone) continue;
        if (o.detected >= d.onset && o.detected <= d.onset + 2) ++detected3;
        within += o.within_20 ? 1 : 0;
        covered += o.covered ? 1 : 0;
      }
      if (f == Fault::kNone) {
        clean_days += days;
        clean_alarms += others;
        std::printf("| %s | %zu | - | - | - | %zu in %.1f glider-days |\n", name(f), ok, others, days);
      } else {
        fault_days += days;
        fault_alarms += others;
        std::printf("| %s | %zu | %zu | %zu | %zu | %zu in %.1f glider-days |\n", name(f), ok, detected3, within,
                    covered, others, days);
      }
    }
    std::printf(
        "\nfalse alarms per 100 glider-days: clean SIL %.1f (%zu in %.1f days); other effects in the fault "
        "draws %.1f (%zu in %.1f days)\n",
        clean_days > 0 ? 100.0 * clean_alarms / clean_days : 0.0, clean_alarms, clean_days,
        fault_days > 0 ? 100.0 * fault_alarms / fault_days : 0.0, fault_alarms, fault_days);

    // The real deployments: every one in tests/data/real given as its
    // segments (the binary folders, the per-segment CSV conversions; the
    // merged comet-2016 CSV and gliderflight's six-column set are not
    // segments: docs/health.md).
    std::printf("\nreal deployments (tests/data/real):\n");
    const std::string real = std::string(GLIDER_SOURCE_DIR) + "/tests/data/real/";
    const std::vector<std::pair<std::string, std::vector<std::string>>> deployments{
        {"comet-2016 (.dbd/.ebd)", {real + "dbd/comet-2016"}},
        {"comet-2019 (.dbd/.ebd)", {real + "dbd/comet-2019"}},
        {"comet-2019 (CSV)", {real + "comet-2019-222-02-154.csv", real + "comet-2019-222-02-156.csv"}},
        {"amadeus-2014 (CSV)", {real + "gpl-3.0-or-later/amadeus-2014-204-05-000.csv"}}};
    for (const auto& [deployment, inputs] : deployments) {
      health::HealthOptions o;
      o.inputs = inputs;
      const std::string glider = deployment.substr(0, deployment.find('-'));
      const health::NominalChoice nominal = health::nominal_for({}, {}, glider, cli::boards_dir());
      o.vehicle = nominal.vehicle;
      o.vehicle_source = nominal.source;
      const health::HealthRun r = health::update_health(o);
      double days = 0.0;
      for (const auto& s : r.segments) days += (s.end_s - s.start_s) / 86400.0;
      std::size_t judged = 0;
      for (const auto& s : r.segments) judged += s.judged ? 1 : 0;
      std::printf("  %s: %zu segments (%zu judged), %.3f glider-days: state %s, %zu alert(s)\n", deployment.c_str(),
                  r.segments.size(), judged, days, r.assessment.state.c_str(), r.assessment.alerts.size());
      for (const auto& a : r.assessment.alerts) std::printf("      %s\n", a.message.c_str());
    }

    std::printf(
        "\ncost of one surfacing's update (measure the new segments, assess, write the state), %zu updates: "
        "wall median %.2f s, 90th %.2f s, max %.2f s; CPU median %.2f s, max %.2f s\n",
        update_s.size(), percentile(update_s, 0.5), percentile(update_s, 0.9), percentile(update_s, 1.0),
        percentile(update_cpu_s, 0.5), percentile(update_cpu_s, 1.0));
    return 0;
  });
}
