// SPDX-License-Identifier: Apache-2.0
#pragma once
// The listening side: a TCP acceptor (Boost.Asio) on which each RUDICS call
// arrives as a connection, served on its own thread, at most
// config.max_calls at once. SIGINT/SIGTERM stop it: calls in progress end
// within about a second and their journals and events are still written.
#include <string>

#include "shore_config.hpp"

namespace glider::shore {

// Serves until stopped by a signal. `port_file`, when not empty, receives the
// port actually bound (useful with port 0) once the shore is listening.
void serve_forever(const ShoreConfig& config, const std::string& port_file);

}  // namespace glider::shore
