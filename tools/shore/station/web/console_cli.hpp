// SPDX-License-Identifier: Apache-2.0
#pragma once
// The console's command line inside glider-shore: the `serve` options that
// turn it on (--http ADDR:PORT ...) and the `user add` subcommand.
#include <CLI/CLI.hpp>
#include <string>

#include "console_config.hpp"
#include "glider/cli/tool.hpp"

namespace glider::shore::web {

struct ConsoleOptions {
  std::string http;  // "ADDR:PORT"; empty = no console
  ConsoleConfig config;
  std::string users_file;
  std::string sessions_file;
  // user add
  CLI::App* user = nullptr;
  std::string user_name, role = "pilot";
};

void add_console_options(glider::cli::Tool& tool, CLI::App* serve, CLI::App& app, ConsoleOptions& options);
// Fills in what depends on the root and this program's path (defaults, lookups); throws on a bad --http.
void finish_console_config(ConsoleOptions& options, const std::string& root, const std::string& self_path);
// `glider-shore user add NAME --role R`: the password from standard input (one line; no echo on a terminal).
int run_user_add(ConsoleOptions& options, const std::string& root);

}  // namespace glider::shore::web
