// SPDX-License-Identifier: Apache-2.0
#include "sessions.hpp"

#include "password_hash.hpp"

namespace glider::shore::web {

std::string Sessions::open(const std::string& user, const std::string& role, double now) {
  Session session{user, role, random_hex(32), now + ttl_s_};
  std::string token = random_hex(32);
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto it = sessions_.begin(); it != sessions_.end();) {  // forget the expired ones
    it = it->second.expires_unix <= now ? sessions_.erase(it) : std::next(it);
  }
  sessions_[token] = session;
  return token;
}

std::optional<Session> Sessions::find(const std::string& token, double now) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = sessions_.find(token);
  if (it == sessions_.end()) return std::nullopt;
  if (it->second.expires_unix <= now) {
    sessions_.erase(it);
    return std::nullopt;
  }
  return it->second;
}

void Sessions::close(const std::string& token) {
  std::lock_guard<std::mutex> lock(mutex_);
  sessions_.erase(token);
}

}  // namespace glider::shore::web
