// SPDX-License-Identifier: Apache-2.0
#pragma once
// The pilot's actions from the page (docs/console.md, "Actions"): queue a .ma/.mi
// (rehearsed first by `glider-forecast rehearse` when that program is there,
// CONTRACTS.md), queue a console command, cancel a queued item. Every input is
// checked here (names, sizes, characters); every action, refused or done, is
// one JSON line in ROOT/GLIDER/actions.journal with the user who did it.
#include <nlohmann/json.hpp>
#include <string>

#include "console_config.hpp"

namespace glider::shore::web {

struct ActionResult {
  int status = 200;  // HTTP status: 200 done, 400 bad input, 404 nothing to cancel, 409 rehearsal says no
  nlohmann::json body;
};

bool valid_upload_name(const std::string& name);  // NAME.ma / NAME.mi, plain, <= 64
bool valid_command(const std::string& command);   // 1-128 printable ASCII

ActionResult queue_file(const ConsoleConfig& config, const std::string& glider, const std::string& user,
                        const std::string& name, const std::string& content, bool force);
ActionResult queue_command_action(const ConsoleConfig& config, const std::string& glider, const std::string& user,
                                  const std::string& command);
ActionResult cancel_file(const ConsoleConfig& config, const std::string& glider, const std::string& user,
                         const std::string& name);
ActionResult cancel_command(const ConsoleConfig& config, const std::string& glider, const std::string& user,
                            std::size_t index, const std::string& command);
// Writes one line to the glider's actions.journal (the alerts' acknowledgements too).
void journal_action(const ConsoleConfig& config, const std::string& glider, nlohmann::json entry);

// The rehearsal program: given, else glider-forecast beside this program's build folder or on PATH; "" if none.
std::string find_forecast_program(const std::string& given, const std::string& self_path);

}  // namespace glider::shore::web
