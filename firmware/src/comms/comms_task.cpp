// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/comms/comms_task.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string_view>

namespace glider::fw::comms {
namespace {

constexpr std::size_t kReadPerCycle = 512;    // console bytes taken per cycle
constexpr std::size_t kWritePerCycle = 1024;  // dialog bytes offered per cycle (the modem takes what fits)
constexpr double kDefaultCallbackMin = 30.0;  // GliderDOS left idle: hang up, call again after this
constexpr double kGliderDosIdleS = 600.0;     // ... once nobody has typed for this long
constexpr double kLogWaitS = 30.0;            // a stuck log writer delays the call at most this long

hal::Micros micros(double seconds) { return static_cast<hal::Micros>(std::llround(seconds * 1e6)); }

double nmea(double degrees) {
  const double a = std::fabs(degrees);
  const double whole = std::floor(a);
  return std::copysign(whole * 100.0 + (a - whole) * 60.0, degrees);
}

}  // namespace

const char* to_string(CommsState state) {
  switch (state) {
    case CommsState::kIdle:
      return "idle";
    case CommsState::kGpsWait:
      return "gps_wait";
    case CommsState::kModemStart:
      return "modem_start";
    case CommsState::kSignal:
      return "signal";
    case CommsState::kDial:
      return "dial";
    case CommsState::kDialog:
      return "dialog";
    case CommsState::kCallbackWait:
      return "callback_wait";
    case CommsState::kFinalGps:
      return "final_gps";
    case CommsState::kHangup:
      return "hangup";
    case CommsState::kDone:
      return "done";
  }
  return "?";
}

CommsTask::CommsTask(FlightSoftware& flight, hal::Modem& modem, hal::GpsReceiver& gps, hal::LogSink& log_sink,
                     const CommsConfig& config, FileTransfer* transfer, MissionReloader* reloader)
    : flight_(flight),
      modem_(modem),
      gps_(gps),
      log_sink_(log_sink),
      config_(config),
      transfer_(transfer),
      reloader_(reloader),
      stream_(modem),
      at_(modem),
      console_(*this, parameters_, transfer, out_),
      u_callback_max_min_(config.callback_max_min) {
  flight_.set_surface_hold(true);
  // The dialog's sensors: log columns by name (unknown names are printed as never seen).
  for (std::size_t i = 0; i < config_.sensor_count && i < kMaxDialogSensors; ++i) {
    const std::string_view name(config_.sensors[i].data());
    sensor_column_[i] = -1;
    sensors_[i].name = config_.sensors[i].data();
    sensors_[i].unit = "nodim";
    for (std::size_t c = 0; c < hal::kLogColumns.size(); ++c) {
      if (hal::kLogColumns[c].name == name && hal::kLogColumns[c].value != nullptr) {
        sensor_column_[i] = static_cast<std::int32_t>(c);
        sensors_[i].unit = hal::kLogColumns[c].unit.data();
      }
    }
    ++sensor_count_;
  }
  // What the pilot may put and get (docs/comms.md, Commands).
  static constexpr config::Range kPrintout{10.0, 3600.0, "s"};
  static constexpr config::Range kKeystroke{0.0, 86400.0, "s"};
  static constexpr config::Range kCallbackMax{1.0, 1440.0, "min"};
  (void)parameters_.add("u_printout_cycle_time", kPrintout, &config_.printout_cycle_s);
  (void)parameters_.add("u_keystroke_wait_time", kKeystroke, &config_.keystroke_wait_s);
  (void)parameters_.add("u_iridium_max_time_til_callback", kCallbackMax, &u_callback_max_min_);
}

bool CommsTask::write(const hal::FlightLogRecord& r) {
  for (std::size_t i = 0; i < sensor_count_; ++i) {
    if (sensor_column_[i] < 0) continue;
    const double v = hal::kLogColumns[static_cast<std::size_t>(sensor_column_[i])].value(r);
    if (!std::isfinite(v)) continue;
    sensors_[i].value = v;
    sensors_[i].valid = true;
    sensor_time_us_[i] = r.time_us;
  }
  if (std::isfinite(r.m_lat) && std::isfinite(r.m_lon)) {
    dr_ = {true, r.m_lat, r.m_lon, 0.0};
    dr_us_ = r.time_us;
  }
  if (std::isfinite(r.m_gps_lat) && std::isfinite(r.m_gps_lon)) {
    gps_fix_ = {true, r.m_gps_lat, r.m_gps_lon, 0.0};
    gps_us_ = r.time_us;
  }
  if (r.x_abort_cause != 0 && (!have_record_ || last_record_.x_abort_cause == 0)) {
    ++aborts_;
    last_abort_ = static_cast<AbortCause>(r.x_abort_cause);
    last_abort_us_ = r.time_us;
    std::snprintf(last_abort_segment_, sizeof last_abort_segment_, "%s", segment_name_);
  }
  segment_ = r.x_segment;
  last_record_ = r;
  have_record_ = true;
  return log_sink_.write(r);
}

bool CommsTask::mission_running() const { return !flight_.complete(); }

void CommsTask::end_mission() {
  flight_.end_mission();
  out_.append("Mission ended by the operator. GliderDOS: type `run` or `sequence` to fly it again\r\n");
}

void CommsTask::resume_mission() {
  if (!mission_running()) {
    out_.append("No mission to resume (type `run`)\r\n");
    return;
  }
  resume_ = true;
  out_.append("Resuming the mission\r\n");
}

void CommsTask::reread_mafiles() {
  refusal_by_ = "Control-F";
  if (reloader_ == nullptr) {
    std::snprintf(refusal_, sizeof refusal_, "no mission files to re-read on this vehicle");
  } else if (reloader_->reread(flight_, refusal_, sizeof refusal_)) {
    refusal_[0] = '\0';
    out_.append("mafiles re-read: the new plan is flown from its first waypoint\r\n");
    return;
  }
  out_.appendf("mafiles refused (the old plan is flown): %s\r\n", refusal_);
}

void CommsTask::print_prompt() {
  // GliderDOS's prompt: how the last mission ended (N normal or by the
  // pilot, A abort with its code) or I while one is in progress.
  const bool aborted = flight_.phase() == Phase::kAbort;
  const char letter = aborted ? 'A' : flight_.complete() ? 'N' : 'I';
  const int code = aborted ? static_cast<int>(flight_.abort_cause()) : -1;
  out_.appendf("GliderDos %c %d >", letter, code);
}

void CommsTask::transfer_ended(const TransferProgress& p) {
  out_.appendf("\r\ntransfer %s: %d file(s) done, %d failed, %llu bytes\r\n",
               p.state == TransferState::kDone ? "complete" : "failed", p.files_done, p.files_failed,
               static_cast<unsigned long long>(p.bytes));
  // A received .ma/.mi is used only once it passed the launch validation.
  for (std::size_t i = 0; i < transfer_->received_count(); ++i) {
    const char* path = transfer_->received_path(i);
    const std::size_t n = std::strlen(path);
    const bool mission_file = n > 3 && (std::strcmp(path + n - 3, ".ma") == 0 || std::strcmp(path + n - 3, ".mi") == 0);
    if (!mission_file) continue;
    const char* name = std::strrchr(path, '/') != nullptr ? std::strrchr(path, '/') + 1 : path;
    char why[sizeof refusal_] = {};
    if (reloader_ != nullptr && reloader_->install(flight_, path, why, sizeof why)) {
      out_.appendf("%s accepted: the new plan is flown from its first waypoint\r\n", name);
    } else {
      if (why[0] == '\0') std::snprintf(why, sizeof why, "no mission layer to validate it on this vehicle");
      std::snprintf(refusal_, sizeof refusal_, "%s", why);
      refusal_by_ = name;
      out_.appendf("%s refused (the old plan is flown): %s\r\n", name, refusal_);
    }
  }
  print_prompt();
}

void CommsTask::device_report() {
  const GuardCounts& g = flight_.actuator_guard_counts();
  (void)g;
  out_.appendf("device report: modem AT timeouts %u, malformed replies %u, overlong replies %u\r\n", at_.timeouts(),
               at_.malformed_lines(), at_.overlong_lines());
  out_.appendf("device report: log rows lost %llu, dialog text dropped %llu bytes\r\n",
               static_cast<unsigned long long>(flight_.log_rows_lost()),
               static_cast<unsigned long long>(out_.dropped()));
  out_.appendf("device report: calls %u connected %u dropped %u, surfacings %u without a call %u\r\n",
               stats_.dial_attempts, stats_.calls_connected, stats_.carrier_drops, stats_.surfacings,
               stats_.surfacings_without_call);
}

void CommsTask::callback(double minutes) {
  if (!(minutes <= u_callback_max_min_)) {
    out_.appendf("ERROR: callback minutes value %g is outside the allowed range [1, %g] min\r\n", minutes,
                 u_callback_max_min_);
    return;
  }
  callback_minutes_ = minutes;
  out_.appendf("Hanging up: calling back in %g minutes\r\n", minutes);
}

bool CommsTask::run_mission() {
  if (!flight_.restart_mission()) return false;
  out_.append("Mission restarted\r\n");
  resume_ = true;
  return true;
}

void CommsTask::exit_reset() {
  out_.append("exit reset: the firmware restarts after the hang-up\r\n");
  reset_requested_ = true;
}

bool CommsTask::fresh_fix_since(hal::Micros since_us) const { return gps_fix_.valid && gps_us_ >= since_us; }

const char* CommsTask::number_to_dial() const {
  const bool secondary = config_.secondary_number[0] != '\0' && dials_ >= config_.dial_tries_per_number;
  return secondary ? config_.secondary_number : config_.primary_number;
}

void CommsTask::enter(CommsState state, hal::Micros now_us) {
  state_ = state;
  entered_us_ = now_us;
  step_ = 0;
  tries_ = 0;
}

void CommsTask::give_up(hal::Micros now_us) {
  if (!connected_this_surfacing_) ++stats_.surfacings_without_call;
  enter(CommsState::kHangup, now_us);
}

void CommsTask::print_dialog_now(hal::Micros now_us) {
  last_print_us_ = now_us;
  ++stats_.dialogs_printed;
  std::array<DialogSensor, kMaxDialogSensors> sensors = sensors_;
  for (std::size_t i = 0; i < sensor_count_; ++i) sensors[i].age_s = hal::to_seconds(now_us - sensor_time_us_[i]);
  DialogSnapshot s;
  s.vehicle_name = config_.vehicle_name;
  if (flight_.phase() == Phase::kAbort) {
    s.because = "Abort";
    s.behavior = "abend";
    s.start_when = 0.0;
  } else if (flight_.complete()) {
    s.because = "Mission done";
    s.start_when = 1.0;
  } else if (flight_.navigator().surfaced_by_start_when() == 9) {
    s.because = "Every when secs";
    s.start_when = 9.0;
  } else if (flight_.navigator().surfaced_by_start_when() == 12) {
    s.because = "No comms for when secs";  // this project's wording: no public transcript found
    s.start_when = 12.0;
  } else {
    s.because = "Stack idle";
    s.start_when = 1.0;
  }
  s.mission_name = config_.mission_name;
  s.segment_name = segment_name_;
  s.mission_number = config_.mission_number;
  s.segment_number = segment_;
  s.utc_s = config_.utc_at_zero_s + hal::to_seconds(now_us);
  s.mission_time_s = hal::to_seconds(now_us);
  s.dr = dr_;
  s.dr.age_s = hal::to_seconds(now_us - dr_us_);
  s.gps = gps_fix_;
  s.gps.age_s = hal::to_seconds(now_us - gps_us_);
  s.gps_invalid = gps_invalid_;
  s.gps_invalid.age_s = hal::to_seconds(now_us - gps_invalid_us_);
  s.sensors = std::span<const DialogSensor>(sensors.data(), sensor_count_);
  DialogDevices d;
  const std::uint32_t errors = at_.timeouts() + static_cast<std::uint32_t>(flight_.log_rows_lost());
  const std::uint32_t warnings = at_.malformed_lines() + at_.overlong_lines();
  const std::uint32_t oddities = console_.stats().refused;
  for (int k = 0; k < 3; ++k) {
    d.errors[k] = errors;
    d.warnings[k] = warnings;
    d.oddities[k] = oddities;
  }
  s.devices = d;
  s.aborts.total = aborts_;
  s.aborts.last_cause = last_abort_;
  s.aborts.last_time_utc_s = config_.utc_at_zero_s + hal::to_seconds(last_abort_us_);
  s.aborts.last_segment = last_abort_segment_;
  s.aborts.last_mission = config_.mission_name;
  s.refusal = refusal_;
  s.keystroke_wait_s = config_.keystroke_wait_s;
  s.refusal_by = refusal_by_;
  print_dialog(s, out_);
  print_prompt();
  refusal_[0] = '\0';  // said once, in this dialog
}

void CommsTask::flush_output() {
  std::size_t offered = 0;
  for (int k = 0; k < 2 && !out_.empty() && offered < kWritePerCycle; ++k) {
    std::span<const std::uint8_t> chunk = out_.front();
    if (chunk.size() > kWritePerCycle - offered) chunk = chunk.first(kWritePerCycle - offered);
    const std::size_t n = modem_.write(chunk);
    out_.consume(n);
    if (n > 0) {
      drained_at_us_ =
          std::max(drained_at_us_, now_us_) + micros(static_cast<double>(n) / std::max(config_.link_bytes_per_s, 1.0));
    }
    offered += chunk.size();
    stats_.bytes_sent += n;
    if (n < chunk.size()) break;  // the link is full this cycle
  }
  stats_.output_dropped = out_.dropped();
}

void CommsTask::step_modem(hal::Micros now_us) {
  if (hal::to_seconds(now_us - modem_start_us_) >= config_.dial_budget_s && !at_.busy()) {
    give_up(now_us);
    return;
  }
  const hal::Micros at_timeout = micros(config_.at_timeout_s);
  if (state_ == CommsState::kModemStart) {
    if (!at_.busy()) {
      if (!at_.start(step_ == 0 ? "AT" : "ATE0", now_us, at_timeout)) give_up(now_us);
      return;
    }
    const AtResult r = at_.poll(now_us);
    if (r == AtResult::kPending) return;
    if (r == AtResult::kOk) {
      tries_ = 0;
      if (++step_ == 2) enter(CommsState::kSignal, now_us);
    } else if (++tries_ >= config_.at_retries) {
      give_up(now_us);
    }
    return;
  }
  if (state_ == CommsState::kSignal) {
    if (!at_.busy()) {
      if (step_ == 1 && hal::to_seconds(now_us - entered_us_) < config_.signal_retry_s) return;
      entered_us_ = now_us;
      step_ = 0;
      if (!at_.start("AT+CSQ", now_us, at_timeout)) give_up(now_us);
      return;
    }
    const AtResult r = at_.poll(now_us);
    if (r == AtResult::kPending) return;
    if (r == AtResult::kOk && at_.signal_quality() >= config_.min_signal) {
      enter(CommsState::kDial, now_us);
      return;
    }
    // Too few satellites (ask again later), or no answer (a few times, then give up).
    if (r != AtResult::kOk && ++tries_ >= config_.at_retries) {
      give_up(now_us);
      return;
    }
    step_ = 1;
    return;
  }
  // kDial
  if (!at_.busy()) {
    if (dials_ >= 2 * config_.dial_tries_per_number) {
      give_up(now_us);
      return;
    }
    char command[AtDriver::kMaxCommand];
    std::snprintf(command, sizeof command, "ATD%s", number_to_dial());
    ++dials_;
    ++stats_.dial_attempts;
    if (!at_.start(command, now_us, micros(config_.dial_timeout_s))) give_up(now_us);
    return;
  }
  const AtResult r = at_.poll(now_us);
  if (r == AtResult::kPending) return;
  if (r == AtResult::kConnect) {
    ++stats_.calls_connected;
    stats_.last_call_us = now_us;
    connected_this_surfacing_ = true;
    flight_.note_comms(now_us);
    enter(CommsState::kDialog, now_us);
    last_key_us_ = now_us;
    shore_typed_ = false;
    print_dialog_now(now_us);  // every call shows the dialog at least once
    if (console_.feed(at_.data_after_connect())) {
      last_key_us_ = now_us;
      shore_typed_ = true;
    }
    stats_.bytes_received += at_.data_after_connect().size();
    at_.clear_data_after_connect();
    return;
  }
  // BUSY, NO CARRIER, NO ANSWER, ERROR, timeout: check the sky again, then the next try.
  enter(CommsState::kSignal, now_us);
}

bool CommsTask::saw_no_carrier(std::span<const std::uint8_t> bytes) {
  static constexpr std::string_view kNoCarrier = "NO CARRIER";
  for (const std::uint8_t b : bytes) {
    if (b == static_cast<std::uint8_t>(kNoCarrier[no_carrier_match_])) {
      if (++no_carrier_match_ == kNoCarrier.size()) {
        no_carrier_match_ = 0;
        return true;
      }
    } else {
      no_carrier_match_ = b == static_cast<std::uint8_t>(kNoCarrier[0]) ? 1 : 0;
    }
  }
  return false;
}

void CommsTask::step_dialog(hal::Micros now_us) {
  if (modem_.carrier() == hal::Carrier::kLost || carrier_gone_) {
    carrier_gone_ = false;
    no_carrier_match_ = 0;
    ++stats_.carrier_drops;
    if (transferring_ && transfer_ != nullptr) transfer_->cancel();
    transferring_ = false;
    out_.clear();
    const bool budget_left = hal::to_seconds(now_us - modem_start_us_) < config_.dial_budget_s;
    if (!resume_ && budget_left && dials_ < 2 * config_.dial_tries_per_number) {
      enter(CommsState::kSignal, now_us);  // call again
    } else {
      enter(CommsState::kFinalGps, now_us);
    }
    return;
  }
  if (transferring_ && transfer_ != nullptr) {
    // The command's answer goes out before the engine's first byte.
    if (!out_.empty()) {
      flush_output();
      return;
    }
    const TransferProgress p = transfer_->poll(now_us, stream_);
    if (p.state == TransferState::kRunning) return;
    transferring_ = false;
    last_key_us_ = now_us;
    transfer_ended(p);
  }
  std::array<std::uint8_t, kReadPerCycle> input{};
  const std::size_t n = modem_.read(input);
  stats_.bytes_received += n;
  // A line without DCD: the modem's own "NO CARRIER" ends the call (next cycle).
  if (modem_.carrier() == hal::Carrier::kUnknown && saw_no_carrier(std::span<const std::uint8_t>(input.data(), n))) {
    carrier_gone_ = true;
    return;
  }
  if (n > 0 && console_.feed(std::span<const std::uint8_t>(input.data(), n))) {
    last_key_us_ = now_us;
    shore_typed_ = true;
  }
  const bool running = mission_running();
  // The pilot's Control-C left the vehicle at GliderDOS: it stays up and keeps
  // calling. A mission over by itself (or an abort) makes this one call.
  const bool at_gliderdos = flight_.ended_by_operator();
  // The keystroke wait counts from the last key; a shore in the middle of its
  // work (it has typed this call) gets at least the reply window for its next line.
  const double wait_s =
      shore_typed_ ? std::max(config_.keystroke_wait_s, config_.reply_window_s) : config_.keystroke_wait_s;
  const bool idle_s_over = hal::to_seconds(now_us - last_key_us_) >= wait_s;
  // Nothing is hung up on before the last text has left the modem.
  const bool sent = out_.empty() && now_us >= drained_at_us_;
  if (callback_minutes_ > 0.0 || reset_requested_) {
    if (sent) enter(CommsState::kHangup, now_us);
  } else if (resume_ || (!at_gliderdos && idle_s_over)) {
    if (sent) enter(CommsState::kFinalGps, now_us);
  } else if (at_gliderdos && hal::to_seconds(now_us - last_key_us_) >= kGliderDosIdleS) {
    callback_minutes_ = kDefaultCallbackMin;  // GliderDOS left alone: hang up, call again
  } else if (running && hal::to_seconds(now_us - last_print_us_) >= config_.printout_cycle_s && !transferring_) {
    print_dialog_now(now_us);
  }
  // Also in the cycle a command starts a transfer: its answer (the echo, "Sending
  // N file(s)") leaves before the engine's first byte, which comes next cycle.
  flush_output();
}

void CommsTask::step_hangup(hal::Micros now_us) {
  const double in_state_s = seconds_in_state(now_us);
  switch (step_) {
    case 0:  // data mode: guard time of silence, then the escape
      if (!connected_this_surfacing_ || stats_.last_call_us < 0 || modem_.carrier() == hal::Carrier::kLost) {
        step_ = 3;
      } else if (in_state_s >= config_.escape_guard_s) {
        step_ = at_.start("+++", now_us, micros(config_.escape_guard_s + config_.at_timeout_s), true) ? 2 : 3;
      }
      return;
    case 2:
      if (at_.poll(now_us) != AtResult::kPending) step_ = 3;  // OK, or gone already: ATH anyway
      return;
    case 3:
      step_ = at_.start("ATH", now_us, micros(config_.at_timeout_s)) ? 4 : 5;
      return;
    case 4:
      if (at_.poll(now_us) == AtResult::kPending) return;
      step_ = 5;
      [[fallthrough]];
    default:
      if (callback_minutes_ > 0.0) {
        callback_at_us_ = now_us + micros(callback_minutes_ * 60.0);
        callback_minutes_ = 0.0;
        enter(CommsState::kCallbackWait, now_us);
        return;
      }
      if (resume_ && mission_running()) flight_.request_resume();
      enter(CommsState::kDone, now_us);
      return;
  }
}

void CommsTask::run(hal::Micros now_us) {
  now_us_ = now_us;
  const bool up = flight_.at_surface();
  if (up) {
    const hal::GpsFix fix = gps_.read();
    if (!fix.valid && fix.time_us > gps_invalid_us_ && std::isfinite(fix.latitude_deg) &&
        std::isfinite(fix.longitude_deg) && fix.time_us > 0) {
      gps_invalid_ = {true, nmea(fix.latitude_deg), nmea(fix.longitude_deg), 0.0};
      gps_invalid_us_ = fix.time_us;
    }
  }
  switch (state_) {
    case CommsState::kIdle:
      if (up && !was_at_surface_) {
        ++stats_.surfacings;
        surfaced_us_ = now_us;
        connected_this_surfacing_ = false;
        resume_ = false;
        dials_ = 0;
        format_segment_name(segment_name_, sizeof segment_name_, config_.vehicle_name,
                            config_.utc_at_zero_s + hal::to_seconds(now_us), config_.mission_number, segment_);
        enter(CommsState::kGpsWait, now_us);
      }
      break;
    case CommsState::kGpsWait: {
      // The segment closed at this surfacing is written (and closed) before
      // the call, so the call's first `send` offers it; bounded.
      const bool log_written = log_progress_ == nullptr || seconds_in_state(now_us) >= kLogWaitS ||
                               log_progress_->written_through(surfaced_us_);
      if (log_written && (fresh_fix_since(surfaced_us_) || seconds_in_state(now_us) >= config_.gps_wait_s)) {
        modem_start_us_ = now_us;
        enter(CommsState::kModemStart, now_us);
      }
      break;
    }
    case CommsState::kModemStart:
    case CommsState::kSignal:
    case CommsState::kDial:
      step_modem(now_us);
      break;
    case CommsState::kDialog:
      step_dialog(now_us);
      break;
    case CommsState::kCallbackWait:
      if (now_us >= callback_at_us_) {
        dials_ = 0;
        modem_start_us_ = now_us;
        enter(CommsState::kModemStart, now_us);
      }
      break;
    case CommsState::kFinalGps:
      if (fresh_fix_since(entered_us_) || seconds_in_state(now_us) >= config_.final_gps_wait_s) {
        enter(CommsState::kHangup, now_us);
      }
      break;
    case CommsState::kHangup:
      step_hangup(now_us);
      break;
    case CommsState::kDone:
      if (!up) enter(CommsState::kIdle, now_us);
      break;
  }
  was_at_surface_ = up;
  // Held except once done: under water the hold means nothing, and so it is
  // already on in the first cycle up, before this task has seen the surface.
  flight_.set_surface_hold(state_ != CommsState::kDone);
}

}  // namespace glider::fw::comms
