// SPDX-License-Identifier: Apache-2.0
#include "sessions.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "password_hash.hpp"
#include "user_accounts.hpp"

namespace glider::shore::web {

namespace {

constexpr const char* kSchema = "glider-console-sessions/1";

bool lower_hex(const std::string& text, std::size_t size) {
  if (text.size() != size) return false;
  for (const char c : text) {
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

// One entry of the file, checked as any input: the text says what is wrong.
std::string check_entry(const nlohmann::json& e) {
  if (!e.is_object()) return "not an object";
  for (const char* key : {"token_sha256", "user", "role", "csrf"}) {
    if (!e.contains(key) || !e[key].is_string()) return std::string("'") + key + "' missing or not text";
  }
  if (!lower_hex(e["token_sha256"], 64)) return "token_sha256: not 64 hex digits";
  if (!lower_hex(e["csrf"], 64)) return "csrf: not 64 hex digits";
  if (!valid_user_name(e["user"])) return "user: not a user name";
  if (!valid_role(e["role"])) return "role: allowed are pilot, viewer";
  if (!e.contains("expires_unix") || !e["expires_unix"].is_number() ||
      !std::isfinite(e["expires_unix"].get<double>())) {
    return "expires_unix: missing or not a finite number";
  }
  return "";
}

}  // namespace

std::string Sessions::load(const std::function<bool(const std::string&, const std::string&)>& still_valid, double now) {
  std::lock_guard<std::mutex> lock(mutex_);
  sessions_.clear();
  if (file_.empty() || !std::filesystem::exists(file_)) return "";
  std::string problem;
  std::map<std::string, Session> read;
  try {
    std::ifstream in(file_);
    std::stringstream text;
    text << in.rdbuf();
    const nlohmann::json j = nlohmann::json::parse(text.str());
    if (!j.is_object() || j.value("schema", "") != kSchema || !j.contains("sessions") || !j["sessions"].is_array()) {
      problem = std::string("not a ") + kSchema + " file";
    } else {
      std::size_t index = 0;
      for (const nlohmann::json& e : j["sessions"]) {
        const std::string why = check_entry(e);
        if (!why.empty()) {
          problem = "session " + std::to_string(index) + ": " + why;
          break;
        }
        const Session s{e["user"], e["role"], e["csrf"], e["expires_unix"].get<double>()};
        if (s.expires_unix > now && s.expires_unix <= now + ttl_s_ && still_valid(s.user, s.role))
          read[e["token_sha256"]] = s;
        ++index;
      }
    }
  } catch (const std::exception& error) {
    problem = std::string("not JSON: ") + error.what();
  }
  if (!problem.empty()) {
    read.clear();
    problem = file_.string() + ": " + problem + ": nobody stays logged in";
  }
  sessions_ = std::move(read);
  try {
    save_locked(now);  // what is left: expired, unknown or damaged entries go at once
  } catch (const std::exception& error) {
    problem += (problem.empty() ? "" : "; ") + std::string(error.what());
  }
  return problem;
}

std::string Sessions::open(const std::string& user, const std::string& role, double now) {
  Session session{user, role, random_hex(32), now + ttl_s_};
  std::string token = random_hex(32);
  std::lock_guard<std::mutex> lock(mutex_);
  sessions_[sha256_hex(token)] = session;
  try {
    save_locked(now);
  } catch (const std::exception& error) {  // logged in all the same; a restart would log this one out
    std::fprintf(stderr, "glider-shore console: %s\n", error.what());
  }
  return token;
}

std::optional<Session> Sessions::find(const std::string& token, double now) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = sessions_.find(sha256_hex(token));
  if (it == sessions_.end()) return std::nullopt;
  if (it->second.expires_unix <= now) {
    sessions_.erase(it);
    return std::nullopt;
  }
  return it->second;
}

void Sessions::close(const std::string& token) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (sessions_.erase(sha256_hex(token)) == 0) return;
  try {
    save_locked(0.0);
  } catch (const std::exception& error) {  // logged out here; the file keeps it until it expires or the next write
    std::fprintf(stderr, "glider-shore console: %s\n", error.what());
  }
}

void Sessions::save_locked(double now) {
  for (auto it = sessions_.begin(); it != sessions_.end();) {  // forget the expired ones
    it = it->second.expires_unix <= now ? sessions_.erase(it) : std::next(it);
  }
  if (file_.empty()) return;
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [hash, s] : sessions_) {
    list.push_back({{"token_sha256", hash},
                    {"user", s.user},
                    {"role", s.role},
                    {"csrf", s.csrf},
                    {"expires_unix", s.expires_unix}});
  }
  write_private_file(file_, nlohmann::json{{"schema", kSchema}, {"sessions", list}}.dump(1) + "\n");
}

}  // namespace glider::shore::web
