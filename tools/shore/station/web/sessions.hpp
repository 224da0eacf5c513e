// SPDX-License-Identifier: Apache-2.0
#pragma once
// Logged-in users: a random 256-bit session token (the cookie), its user and
// role, a CSRF token (sent back by the page's script in X-CSRF-Token on every
// action) and an absolute expiry. With a file (glider-shore serve: ROOT/
// console.sessions) they survive a restart of the shore: the file is
// rewritten whole (mode 0600, temporary + rename) on every login and logout,
// and holds each cookie only as its SHA-256 (a copy of the file logs nobody in).
#include <filesystem>
#include <functional>
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
  // `file` empty: in memory only.
  explicit Sessions(double ttl_s, std::filesystem::path file = {}) : ttl_s_(ttl_s), file_(std::move(file)) {}
  // At start: the sessions of the file that are still open and whose user `still_valid` accepts with that
  // role (an account removed or its role changed ends its sessions). Returns "" or why the file was not
  // used (damaged: file, entry and what is wrong; then nobody is logged in and the file is rewritten).
  std::string load(const std::function<bool(const std::string& user, const std::string& role)>& still_valid,
                   double now);
  // Returns the new session's token.
  std::string open(const std::string& user, const std::string& role, double now);
  std::optional<Session> find(const std::string& token, double now);
  void close(const std::string& token);
  double ttl_s() const { return ttl_s_; }

 private:
  void save_locked(double now);  // the file, if any, from sessions_ (expired ones left out)

  double ttl_s_;
  std::filesystem::path file_;
  std::mutex mutex_;
  std::map<std::string, Session> sessions_;  // by the SHA-256 of the token
};

}  // namespace glider::shore::web
