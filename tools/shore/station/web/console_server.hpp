// SPDX-License-Identifier: Apache-2.0
#pragma once
// The pilot's console over HTTP (cpp-httplib, Debian's libcpp-httplib-dev):
// the fleet and glider pages, their JSON, server-sent events, the actions,
// login and sessions. Security model in docs/console.md: loopback without a
// login unless --http-auth; any other address needs the users file, every
// request a session, the actions the pilot role and the session's CSRF token.
#include <memory>
#include <string>
#include <thread>

#include "console_config.hpp"

namespace glider::shore::web {

class ConsoleServer {
 public:
  explicit ConsoleServer(ConsoleConfig config);
  ~ConsoleServer();
  ConsoleServer(const ConsoleServer&) = delete;
  ConsoleServer& operator=(const ConsoleServer&) = delete;

  // Binds (throws if it cannot, or if the configuration is unsafe) and serves on a thread of its own.
  void start();
  void stop();
  unsigned port() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace glider::shore::web
