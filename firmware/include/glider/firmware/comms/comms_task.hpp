// SPDX-License-Identifier: Apache-2.0
#pragma once
// The comms state machine: at each surfacing, GPS wait, modem start and
// signal check, device pick (primary, then secondary number), dial, the
// dialog loop (dialog re-printed every printout_cycle_time, the console,
// file transfers), final GPS fix, hang-up, dive. A PeriodicTask after the
// flight software: every cycle it moves a bounded number of bytes, never
// waits, never allocates; its timers run on the HAL clock only. It holds the
// vehicle at the surface while it works and lets it dive when it is done or
// has given up (the mission goes on without comms: docs/comms.md).
#include <array>
#include <cstdint>

#include "glider/firmware/comms/at_driver.hpp"
#include "glider/firmware/comms/console.hpp"
#include "glider/firmware/comms/file_transfer.hpp"
#include "glider/firmware/comms/modem_stream.hpp"
#include "glider/firmware/comms/parameters.hpp"
#include "glider/firmware/comms/surface_dialog.hpp"
#include "glider/firmware/executive.hpp"
#include "glider/firmware/flight_software.hpp"
#include "glider/hal/gps.hpp"
#include "glider/hal/log_record.hpp"
#include "glider/hal/modem.hpp"

namespace glider::fw::comms {

constexpr std::size_t kMaxDialogSensors = 16;
constexpr std::size_t kTextField = 40;

struct CommsConfig {
  char vehicle_name[kTextField] = "glider";
  char primary_number[kTextField] = "";    // dialled first (Iridium RUDICS: 0088160000xxx)
  char secondary_number[kTextField] = "";  // after dial_tries_per_number failures on the primary ("" none)
  char mission_name[kTextField] = "MISSION.MI";
  std::int32_t mission_number = 0;
  // Sensors of the dialog, log column names (hal::kLogColumns).
  std::array<std::array<char, kTextField>, kMaxDialogSensors> sensors{};
  std::size_t sensor_count = 0;
  double utc_at_zero_s = 0.0;  // UTC (s since 1970) at HAL time 0: the dialog's Curr Time
  // The surface behaviour's arguments (mission plan): 0 = none.
  double gps_wait_s = 120.0;        // gps_wait_time
  double keystroke_wait_s = 300.0;  // keystroke_wait_time (end_action 1)
  double printout_cycle_s = 60.0;   // printout_cycle_time
  // Once the shore has typed in this call, the glider waits at least this long
  // after each answer for its next line, even with a shorter keystroke wait
  // (end_action 2: 0 s): a shore's script types `whoru`, then `send` on the
  // next prompt, and a glider gone between the two lines delivers no file.
  // A shore that never types still sees the glider leave after keystroke_wait_s.
  double reply_window_s = 30.0;
  // The modem.
  double at_timeout_s = 3.0;    // AT, ATE0, AT+CSQ, ATH
  std::int32_t at_retries = 3;  // per command before the modem counts as dead this surfacing
  std::int32_t min_signal = 1;  // +CSQ below this: wait for the satellites, then ask again
  double signal_retry_s = 10.0;
  double dial_timeout_s = 60.0;  // ATD to CONNECT (Iridium call set-up: ~10-30 s)
  std::int32_t dial_tries_per_number = 2;
  double dial_budget_s = 600.0;  // from the modem start: give up calling after this
  double final_gps_wait_s = 60.0;
  double escape_guard_s = 1.0;  // silence before and after "+++"
  // The link's payload rate: what was written is given this long to leave the
  // modem's buffer before the call is hung up (Iridium: ~270 B/s; lower is safer).
  double link_bytes_per_s = 250.0;
  double callback_max_min = 1440.0;
};

// The mission layer's Control-F (re-read the .ma files): validate and, only
// if valid, replace the flown plan. On refusal writes the reason
// (file:line, key, value, range) into `refusal` and leaves the plan.
class MissionReloader {
 public:
  virtual ~MissionReloader() = default;
  virtual bool reread(FlightSoftware& flight, char* refusal, std::size_t size) = 0;
  // A mission file received from shore (zr), complete: validated with the
  // flown mission exactly as at launch; only if valid it joins the mission's
  // files and its plan is flown. Refused: the plan and the files stay.
  virtual bool install(FlightSoftware& /*flight*/, const char* /*received_path*/, char* refusal, std::size_t size) {
    if (size > 0) refusal[0] = '\0';
    return false;
  }
};

// The log's writer, where rows are written after the cycle that made them
// (the target's writer thread): the comms task calls only once the rows up
// to the surfacing are written, so the segment the surfacing closed is a
// whole file, offered to the call's first `send` (in SIL the log is written
// within the cycle: no such wait). `written_through` must not block; it may
// wake the writer.
class LogProgress {
 public:
  virtual ~LogProgress() = default;
  virtual bool written_through(hal::Micros time_us) = 0;
};

enum class CommsState : std::int32_t {
  kIdle = 0,      // under water (or not yet up)
  kGpsWait,       // up: waiting for the first fix (gps_wait_time)
  kModemStart,    // AT, ATE0
  kSignal,        // AT+CSQ until enough satellites
  kDial,          // ATD<number>
  kDialog,        // connected: dialog, console, transfers
  kCallbackWait,  // hung up on `callback N`, redial later
  kFinalGps,      // a last fix before diving
  kHangup,        // +++ ATH
  kDone,          // released the vehicle; back to kIdle once it dives
};

const char* to_string(CommsState state);

struct CommsStats {
  std::uint32_t surfacings = 0;
  std::uint32_t surfacings_without_call = 0;  // gave up: no signal, no answer, no modem
  std::uint32_t dial_attempts = 0;
  std::uint32_t calls_connected = 0;
  std::uint32_t carrier_drops = 0;
  std::uint32_t dialogs_printed = 0;
  std::uint64_t bytes_sent = 0;
  std::uint64_t bytes_received = 0;
  std::uint64_t output_dropped = 0;  // text that did not fit the queue
  hal::Micros last_call_us = -1;     // the last CONNECT (-1: never)
};

// The dialog sees the flight through the log rows: the tap forwards every
// row to the real sink and keeps the dialog's sensors with their times.
class CommsTask final : public PeriodicTask, public hal::LogSink, private ConsoleActions {
 public:
  CommsTask(FlightSoftware& flight, hal::Modem& modem, hal::GpsReceiver& gps, hal::LogSink& log_sink,
            const CommsConfig& config, FileTransfer* transfer = nullptr, MissionReloader* reloader = nullptr);
  CommsTask(const CommsTask&) = delete;
  CommsTask& operator=(const CommsTask&) = delete;

  void run(hal::Micros now_us) override;
  bool write(const hal::FlightLogRecord& record) override;  // the log tap

  // Optional (null: the log is written within the cycle).
  void set_log_progress(LogProgress* progress) { log_progress_ = progress; }
  ParameterTable& parameters() { return parameters_; }
  CommsState state() const { return state_; }
  // A Zmodem transfer (zs, zr, send) is running in the call.
  bool transferring() const { return transferring_; }
  // No call in progress and nothing holding the vehicle up.
  bool idle() const { return state_ == CommsState::kIdle; }
  const CommsStats& stats() const { return stats_; }
  const ConsoleStats& console_stats() const { return console_.stats(); }
  const AtDriver& at() const { return at_; }
  bool reset_requested() const { return reset_requested_; }

 private:
  // ConsoleActions.
  const char* vehicle_name() const override { return config_.vehicle_name; }
  bool mission_running() const override;
  void end_mission() override;
  void resume_mission() override;
  void reread_mafiles() override;
  void device_report() override;
  void callback(double minutes) override;
  bool run_mission() override;
  void exit_reset() override;
  void transfer_started() override { transferring_ = true; }
  void print_prompt() override;
  void transfer_ended(const TransferProgress& progress);

  void enter(CommsState state, hal::Micros now_us);
  void step_modem(hal::Micros now_us);
  void step_dialog(hal::Micros now_us);
  bool saw_no_carrier(std::span<const std::uint8_t> bytes);
  void step_hangup(hal::Micros now_us);
  void give_up(hal::Micros now_us);
  void flush_output();
  void print_dialog_now(hal::Micros now_us);
  bool fresh_fix_since(hal::Micros since_us) const;
  const char* number_to_dial() const;
  double seconds_in_state(hal::Micros now_us) const { return hal::to_seconds(now_us - entered_us_); }

  FlightSoftware& flight_;
  hal::Modem& modem_;
  hal::GpsReceiver& gps_;
  hal::LogSink& log_sink_;
  CommsConfig config_;
  FileTransfer* transfer_;
  MissionReloader* reloader_;
  LogProgress* log_progress_ = nullptr;
  ModemStream stream_;
  AtDriver at_;
  DialogQueue out_;
  ParameterTable parameters_;
  Console console_;

  CommsState state_ = CommsState::kIdle;
  hal::Micros now_us_ = 0;
  hal::Micros entered_us_ = 0;
  hal::Micros surfaced_us_ = 0;
  hal::Micros modem_start_us_ = 0;
  hal::Micros last_key_us_ = 0;
  hal::Micros last_print_us_ = 0;
  hal::Micros callback_at_us_ = 0;
  hal::Micros drained_at_us_ = 0;  // when the bytes written so far have left at link_bytes_per_s
  std::int32_t step_ = 0;          // sub-step within a modem state
  std::int32_t tries_ = 0;         // of the current AT command
  std::int32_t dials_ = 0;         // this surfacing
  bool connected_this_surfacing_ = false;
  bool shore_typed_ = false;  // a keystroke arrived in this call: reply_window_s applies
  bool transferring_ = false;
  bool resume_ = false;
  bool reset_requested_ = false;
  bool was_at_surface_ = false;
  bool carrier_gone_ = false;         // "NO CARRIER" seen on a line without DCD
  std::size_t no_carrier_match_ = 0;  // characters of "NO CARRIER" matched so far
  double callback_minutes_ = 0.0;
  double u_callback_max_min_;  // put-able
  char refusal_[160] = {};
  const char* refusal_by_ = "Control-F";

  // The log tap's view.
  std::array<DialogSensor, kMaxDialogSensors> sensors_{};
  std::array<std::int32_t, kMaxDialogSensors> sensor_column_{};
  std::array<hal::Micros, kMaxDialogSensors> sensor_time_us_{};
  std::size_t sensor_count_ = 0;
  hal::FlightLogRecord last_record_{};
  bool have_record_ = false;
  DialogPosition dr_{}, gps_fix_{}, gps_invalid_{};
  hal::Micros dr_us_ = 0, gps_us_ = 0, gps_invalid_us_ = 0;
  std::int32_t segment_ = 0;
  // Abort history.
  std::uint32_t aborts_ = 0;
  AbortCause last_abort_ = AbortCause::kNone;
  hal::Micros last_abort_us_ = 0;
  char last_abort_segment_[kTextField * 2] = {};
  char segment_name_[kTextField * 2] = {};
  DialogDevices devices_{};
  CommsStats stats_{};
};

}  // namespace glider::fw::comms
