// SPDX-License-Identifier: Apache-2.0
#pragma once
// Logged-in users: a random 256-bit session token (the cookie), its user and
// role, a CSRF token (sent back by the page's script in X-CSRF-Token on every
// action) and an absolute expiry. In memory only: a restart logs everyone out.
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace glider::shore::web {

struct Session {
  std::string user, role, csrf;
  double expires_unix = 0.0;
};

class Sessions {
 public:
  explicit Sessions(double ttl_s) : ttl_s_(ttl_s) {}
  // Returns the new session's token.
  std::string open(const std::string& user, const std::string& role, double now);
  std::optional<Session> find(const std::string& token, double now);
  void close(const std::string& token);
  double ttl_s() const { return ttl_s_; }

 private:
  double ttl_s_;
  std::mutex mutex_;
  std::map<std::string, Session> sessions_;
};

}  // namespace glider::shore::web
