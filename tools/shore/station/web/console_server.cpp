// SPDX-License-Identifier: Apache-2.0
#include "console_server.hpp"

#include <httplib.h>
#include <openssl/crypto.h>
#include <sys/socket.h>

#include <atomic>
#include <boost/asio/ip/address.hpp>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <regex>
#include <stdexcept>

#include "../glider_folders.hpp"
#include "../surface_dialog.hpp"
#include "console_actions.hpp"
#include "console_state.hpp"
#include "password_hash.hpp"
#include "sessions.hpp"
#include "user_accounts.hpp"
#include "utc_time.hpp"

namespace glider::shore::web {
namespace fs = std::filesystem;
using nlohmann::json;

bool is_ip_address(const std::string& address) {
  boost::system::error_code error;
  boost::asio::ip::make_address(address, error);
  return !error;
}

bool is_loopback(const std::string& address) {
  boost::system::error_code error;
  const boost::asio::ip::address parsed = boost::asio::ip::make_address(address, error);
  return !error && parsed.is_loopback();
}

namespace {

constexpr const char* kCookie = "glider_session";
constexpr int kLockoutFailures = 5;
constexpr double kLockoutS = 60.0;
constexpr double kStreamHeartbeatS = 15.0;

// Debian's libcpp-httplib is built with a listen backlog of 5 (CPPHTTPLIB_LISTEN_BACKLOG): 250 browsers
// connecting at once overflow it and the kernel drops SYNs, which clients retry after 1, 3, 7 s. Linux takes
// a second listen(2) on the bound socket as a new backlog; the socket is the server's protected member.
class HttpServer : public httplib::Server {
 public:
  bool widen_backlog(int backlog) { return ::listen(svr_sock_, backlog) == 0; }
};

struct Asset {
  std::string content, type;
};

std::string mime_type(const std::string& name) {
  const std::string ext = fs::path(name).extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".png") return "image/png";
  if (ext == ".svg") return "image/svg+xml";
  return "application/octet-stream";
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Every page and script is read once at start from fixed folders: no request
// path ever reaches the file system except the health plots (name-checked).
std::map<std::string, Asset> load_assets(const fs::path& web_dir, const fs::path& leaflet_dir) {
  std::map<std::string, Asset> assets;
  std::error_code error;
  for (fs::directory_iterator it(web_dir, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name[0] != '.' && it->is_regular_file()) assets["/static/" + name] = {read_file(it->path()), mime_type(name)};
  }
  if (assets.count("/static/fleet.html") == 0) {
    throw std::runtime_error(web_dir.string() + ": the console's pages are not there (--web-dir)");
  }
  for (const char* name : {"leaflet.js", "leaflet.css"}) {
    if (fs::is_regular_file(leaflet_dir / name)) {
      assets[std::string("/leaflet/") + name] = {read_file(leaflet_dir / name), mime_type(name)};
    }
  }
  for (fs::directory_iterator it(leaflet_dir / "images", error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (it->path().extension() == ".png") assets["/leaflet/images/" + name] = {read_file(it->path()), "image/png"};
  }
  return assets;
}

std::string cookie_value(const httplib::Request& req, const std::string& name) {
  const std::string header = req.get_header_value("Cookie");
  std::size_t pos = 0;
  while (pos < header.size()) {
    std::size_t end = header.find(';', pos);
    if (end == std::string::npos) end = header.size();
    std::string item = header.substr(pos, end - pos);
    const std::size_t first = item.find_first_not_of(' ');
    item = first == std::string::npos ? "" : item.substr(first);
    if (item.rfind(name + "=", 0) == 0) return item.substr(name.size() + 1);
    pos = end + 1;
  }
  return "";
}

bool same_secret(const std::string& a, const std::string& b) {
  return !a.empty() && a.size() == b.size() && CRYPTO_memcmp(a.data(), b.data(), a.size()) == 0;
}

// A form field, from a multipart body (the page's FormData) or a urlencoded one.
std::string field(const httplib::Request& req, const std::string& name) {
  if (req.has_file(name)) return req.get_file_value(name).content;
  if (req.has_param(name)) return req.get_param_value(name);
  return "";
}

void send_json(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(body.dump(-1, ' ', false, json::error_handler_t::replace), "application/json");
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  send_json(res, status, {{"ok", false}, {"error", message}});
}

}  // namespace

struct ConsoleServer::Impl {
  ConsoleConfig config;
  bool auth = false;  // every request needs a session
  std::map<std::string, Account> accounts;
  Sessions sessions;
  std::string local_csrf = random_hex(32);
  std::map<std::string, Asset> assets;
  ConsoleState state;
  HttpServer server;
  std::thread thread;
  int bound_port = 0;
  std::atomic<int> streams{0};
  std::mutex lockout_mutex;
  std::map<std::string, std::pair<int, double>> failures;  // user -> failures in a row, locked until

  explicit Impl(ConsoleConfig c)
      : config(std::move(c)), sessions(config.session_ttl_s, config.sessions_file), state(config) {}

  // Who is asking: a session (auth on), or the local pilot (loopback, auth off).
  std::optional<Session> identify(const httplib::Request& req) {
    if (!auth) return Session{config.local_user, "pilot", local_csrf, 0.0};
    const std::string token = cookie_value(req, kCookie);
    if (token.size() != 64) return std::nullopt;
    return sessions.find(token, now_unix());
  }

  // Loopback without login: only a Host naming loopback (a DNS-rebinding page cannot reach us under its own name).
  bool host_allowed(const httplib::Request& req) const {
    if (auth) return true;
    const std::string host = req.get_header_value("Host");
    const std::string port = ":" + std::to_string(bound_port);
    for (const char* name : {"127.0.0.1", "localhost", "[::1]"}) {
      if (host == name || host == std::string(name) + port) return true;
    }
    return false;
  }

  // Actions: a pilot, and the session's CSRF token in X-CSRF-Token.
  std::optional<Session> actor(const httplib::Request& req, httplib::Response& res) {
    std::optional<Session> who = identify(req);
    if (!who) {
      send_error(res, 401, "log in first");
      return std::nullopt;
    }
    if (!same_secret(req.get_header_value("X-CSRF-Token"), who->csrf)) {
      send_error(res, 403, "missing or wrong CSRF token (reload the page)");
      return std::nullopt;
    }
    if (who->role != "pilot") {
      send_error(res, 403, "user '" + who->user + "' is a " + who->role + ": actions need the pilot role");
      return std::nullopt;
    }
    return who;
  }

  void serve_asset(httplib::Response& res, const std::string& key) {
    const auto it = assets.find(key);
    if (it == assets.end()) {
      send_error(res, 404, "no such page");
      return;
    }
    res.set_content(it->second.content, it->second.type);
  }

  void routes();
  void login(const httplib::Request& req, httplib::Response& res);
  void events(const httplib::Request& req, httplib::Response& res);
};

void ConsoleServer::Impl::login(const httplib::Request& req, httplib::Response& res) {
  const std::string user = field(req, "user"), password = field(req, "password");
  if (!auth) {
    send_error(res, 400, "this console needs no login (loopback without --http-auth)");
    return;
  }
  if (!valid_user_name(user) || password.empty() || password.size() > 1024) {
    send_error(res, 400, "user: 1-32 of A-Z a-z 0-9 _ . -; password: 1-1024 characters");
    return;
  }
  const double now = now_unix();
  {
    std::lock_guard<std::mutex> lock(lockout_mutex);
    const auto it = failures.find(user);
    if (it != failures.end() && it->second.second > now) {
      send_error(res, 429, "too many wrong passwords: try again in a minute");
      return;
    }
  }
  const auto account = accounts.find(user);
  // An unknown user costs the same scrypt as a known one (no timing oracle for names).
  const bool ok =
      verify_password(password, account != accounts.end() ? account->second.hash : "scrypt$131072$8$1$00$00");
  if (!ok || account == accounts.end()) {
    std::lock_guard<std::mutex> lock(lockout_mutex);
    auto& [count, until] = failures[user];
    if (++count >= kLockoutFailures) {
      until = now + kLockoutS;
      count = 0;
    }
    send_error(res, 401, "wrong user or password");
    return;
  }
  {
    std::lock_guard<std::mutex> lock(lockout_mutex);
    failures.erase(user);
  }
  const std::string token = sessions.open(user, account->second.role, now);
  const std::optional<Session> session = sessions.find(token, now);
  res.set_header("Set-Cookie", std::string(kCookie) + "=" + token + "; Path=/; HttpOnly; SameSite=Strict; Max-Age=" +
                                   std::to_string(static_cast<long>(config.session_ttl_s)));
  send_json(res, 200, {{"ok", true}, {"user", user}, {"role", account->second.role}, {"csrf", session->csrf}});
}

void ConsoleServer::Impl::events(const httplib::Request&, httplib::Response& res) {
  if (streams.fetch_add(1) >= config.max_streams) {
    streams.fetch_sub(1);
    send_error(res, 503, "too many event streams open; the page falls back to polling");
    return;
  }
  auto seen = std::make_shared<std::uint64_t>(0);
  res.set_header("Cache-Control", "no-store");
  res.set_chunked_content_provider(
      "text/event-stream",
      [this, seen](std::size_t, httplib::DataSink& sink) {
        const std::shared_ptr<const Snapshot> snap = state.wait_change(*seen, kStreamHeartbeatS);
        if (state.stopping()) {
          sink.done();
          return false;
        }
        std::string message = ": still here\n\n";
        if (snap->version != *seen) {
          *seen = snap->version;
          message = "event: change\ndata: {\"version\":" + std::to_string(snap->version) + "}\n\n";
        }
        return sink.write(message.data(), message.size());
      },
      [this](bool) { streams.fetch_sub(1); });
}

void ConsoleServer::Impl::routes() {
  server.set_default_headers({{"X-Content-Type-Options", "nosniff"},
                              {"X-Frame-Options", "DENY"},
                              {"Referrer-Policy", "no-referrer"},
                              {"Content-Security-Policy",
                               "default-src 'self'; img-src 'self' data:; style-src 'self' 'unsafe-inline'; "
                               "frame-ancestors 'none'; form-action 'self'"}});
  // Before any route: the Host check on loopback, and a session for everything but the login page and its assets.
  server.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (!host_allowed(req)) {
      send_error(res, 403, "Host '" + req.get_header_value("Host").substr(0, 64) + "' is not this loopback console");
      return httplib::Server::HandlerResponse::Handled;
    }
    const std::string& path = req.path;
    const bool open =
        path == "/login" || path == "/api/login" || path.rfind("/static/", 0) == 0 || path.rfind("/leaflet/", 0) == 0;
    if (open || identify(req)) return httplib::Server::HandlerResponse::Unhandled;
    if (path.rfind("/api/", 0) == 0) {
      send_error(res, 401, "log in first");
    } else {
      res.set_redirect("/login", 303);
    }
    return httplib::Server::HandlerResponse::Handled;
  });
  server.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr failure) {
    std::string what = "internal error";
    try {
      std::rethrow_exception(failure);
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    send_error(res, 500, what);
  });

  server.Get("/", [this](const httplib::Request&, httplib::Response& res) { serve_asset(res, "/static/fleet.html"); });
  server.Get("/login",
             [this](const httplib::Request&, httplib::Response& res) { serve_asset(res, "/static/login.html"); });
  server.Get(R"(/glider/([A-Za-z0-9_-]{1,32}))",
             [this](const httplib::Request&, httplib::Response& res) { serve_asset(res, "/static/glider.html"); });
  server.Get(R"(/static/([a-z0-9_-]{1,40}\.(html|js|css|png|svg)))",
             [this](const httplib::Request& req, httplib::Response& res) { serve_asset(res, req.path); });
  server.Get(R"(/leaflet/(leaflet\.js|leaflet\.css|images/[a-z0-9_-]{1,40}\.png))",
             [this](const httplib::Request& req, httplib::Response& res) {
               serve_asset(res, req.path);
               res.set_header("Cache-Control", "max-age=3600");
             });

  server.Get("/api/session", [this](const httplib::Request& req, httplib::Response& res) {
    const std::optional<Session> who = identify(req);
    send_json(res, 200,
              {{"user", who->user},
               {"role", who->role},
               {"csrf", who->csrf},
               {"login_required", auth},
               {"rehearsal", config.forecast_program.empty() ? json(nullptr) : json(config.forecast_program)},
               {"max_upload_bytes", config.max_upload_bytes}});
  });
  server.Post("/api/login", [this](const httplib::Request& req, httplib::Response& res) { login(req, res); });
  server.Post("/api/logout", [this](const httplib::Request& req, httplib::Response& res) {
    const std::optional<Session> who = identify(req);
    if (!who || !same_secret(req.get_header_value("X-CSRF-Token"), who->csrf)) {
      send_error(res, 403, "missing or wrong CSRF token");
      return;
    }
    sessions.close(cookie_value(req, kCookie));
    res.set_header("Set-Cookie", std::string(kCookie) + "=; Path=/; HttpOnly; SameSite=Strict; Max-Age=0");
    send_json(res, 200, {{"ok", true}});
  });
  server.Get("/api/fleet", [this](const httplib::Request&, httplib::Response& res) {
    res.set_header("Cache-Control", "no-store");
    res.set_content(state.snapshot()->fleet, "application/json");
  });
  server.Get(R"(/api/gliders/([A-Za-z0-9_-]{1,32}))", [this](const httplib::Request& req, httplib::Response& res) {
    const std::shared_ptr<const Snapshot> snap = state.snapshot();
    const auto it = snap->gliders.find(req.matches[1]);
    if (it == snap->gliders.end()) {
      send_error(res, 404, "no glider '" + std::string(req.matches[1]) + "' has called this shore");
      return;
    }
    res.set_header("Cache-Control", "no-store");
    res.set_content(it->second, "application/json");
  });
  server.Get(R"(/api/gliders/([A-Za-z0-9_-]{1,32})/plots/([A-Za-z0-9_-]{1,64}\.png))",
             [this](const httplib::Request& req, httplib::Response& res) {
               const fs::path file =
                   config.root / std::string(req.matches[1]) / "health" / "plots" / std::string(req.matches[2]);
               if (!valid_glider_name(req.matches[1]) || !fs::is_regular_file(file)) {
                 send_error(res, 404, "no such plot");
                 return;
               }
               res.set_content(read_file(file), "image/png");
             });
  server.Get("/api/events", [this](const httplib::Request& req, httplib::Response& res) { events(req, res); });

  // Actions.
  server.Post(
      R"(/api/gliders/([A-Za-z0-9_-]{1,32})/queue)", [this](const httplib::Request& req, httplib::Response& res) {
        const std::optional<Session> who = actor(req, res);
        if (!who) return;
        if (!req.has_file("file")) {
          send_error(res, 400, "no file in the request (multipart field 'file')");
          return;
        }
        const httplib::MultipartFormData upload = req.get_file_value("file");
        const ActionResult result =
            queue_file(config, req.matches[1], who->user, upload.filename, upload.content, field(req, "force") == "1");
        state.poke();
        send_json(res, result.status, result.body);
      });
  server.Post(
      R"(/api/gliders/([A-Za-z0-9_-]{1,32})/command)", [this](const httplib::Request& req, httplib::Response& res) {
        const std::optional<Session> who = actor(req, res);
        if (!who) return;
        const ActionResult result = queue_command_action(config, req.matches[1], who->user, field(req, "command"));
        state.poke();
        send_json(res, result.status, result.body);
      });
  server.Post(
      R"(/api/gliders/([A-Za-z0-9_-]{1,32})/cancel)", [this](const httplib::Request& req, httplib::Response& res) {
        const std::optional<Session> who = actor(req, res);
        if (!who) return;
        const std::string kind = field(req, "kind");
        ActionResult result;
        if (kind == "file") {
          result = cancel_file(config, req.matches[1], who->user, field(req, "name"));
        } else if (kind == "command") {
          const std::string index = field(req, "index");
          const bool digits =
              !index.empty() && index.size() <= 4 && index.find_first_not_of("0123456789") == std::string::npos;
          result = digits ? cancel_command(config, req.matches[1], who->user, std::stoul(index), field(req, "command"))
                          : ActionResult{400, {{"ok", false}, {"error", "index: a queue position 0-9999"}}};
        } else {
          result = {400, {{"ok", false}, {"error", "kind: file or command"}}};
        }
        state.poke();
        send_json(res, result.status, result.body);
      });
  server.Post("/api/alerts/ack", [this](const httplib::Request& req, httplib::Response& res) {
    const std::optional<Session> who = actor(req, res);
    if (!who) return;
    const std::string id = field(req, "id");
    const std::string glider = field(req, "glider");
    if (id.empty() || id.size() > 200 || !valid_glider_name(glider) || !valid_command(id)) {
      send_error(res, 400, "id and glider of an alert are needed");
      return;
    }
    if (!state.alerts().acknowledge(id, who->user, now_unix())) {
      send_error(res, 404, "no unacknowledged alert '" + id + "'");
      return;
    }
    journal_action(config, glider,
                   {{"utc", format_utc(now_unix())},
                    {"user", who->user},
                    {"action", "ack_alert"},
                    {"alert", id},
                    {"result", "acknowledged"}});
    state.poke();
    send_json(res, 200, {{"ok", true}});
  });
}

ConsoleServer::ConsoleServer(ConsoleConfig config) : impl_(std::make_unique<Impl>(std::move(config))) {}

ConsoleServer::~ConsoleServer() { stop(); }

void ConsoleServer::start() {
  Impl& s = *impl_;
  const ConsoleConfig& c = s.config;
  {
    boost::system::error_code error;
    boost::asio::ip::make_address(c.address, error);
    if (error) throw std::runtime_error("--http " + c.address + ": not an IPv4 or IPv6 address");
  }
  s.auth = c.force_auth || !is_loopback(c.address);
  if (s.auth) {
    if (c.users_file.empty()) throw std::runtime_error("--http off loopback (or --http-auth) needs --users FILE");
    s.accounts = read_accounts(c.users_file);
    if (s.accounts.empty()) throw std::runtime_error(c.users_file.string() + ": no users (glider-shore user add)");
    const std::string note = s.sessions.load(
        [&s](const std::string& user, const std::string& role) {
          const auto account = s.accounts.find(user);
          return account != s.accounts.end() && account->second.role == role;
        },
        now_unix());
    if (!note.empty()) std::fprintf(stderr, "glider-shore console: %s\n", note.c_str());
  }
  s.assets = load_assets(c.web_dir, c.leaflet_dir);
  s.server.new_task_queue = [threads = c.threads] {
    return new httplib::ThreadPool(static_cast<std::size_t>(threads));
  };
  s.server.set_payload_max_length(c.max_upload_bytes + 16 * 1024);  // the file and the form around it
  s.server.set_tcp_nodelay(true);  // headers and body go as separate writes: no 40 ms Nagle/delayed-ACK wait
  s.server.set_keep_alive_timeout(2);
  s.server.set_read_timeout(10);
  s.server.set_write_timeout(10);
  s.routes();
  if (c.port == 0) {
    s.bound_port = s.server.bind_to_any_port(c.address);
  } else {
    s.bound_port = s.server.bind_to_port(c.address, static_cast<int>(c.port)) ? static_cast<int>(c.port) : -1;
  }
  if (s.bound_port <= 0) {
    throw std::runtime_error("--http " + c.address + ":" + std::to_string(c.port) + ": cannot listen there");
  }
  if (!s.server.widen_backlog(1024)) std::fprintf(stderr, "glider-shore console: listen backlog stays at 5\n");
  s.state.start();
  s.thread = std::thread([&s] { s.server.listen_after_bind(); });
  const std::string shown = c.address.find(':') != std::string::npos ? "[" + c.address + "]" : c.address;
  std::fprintf(stderr, "glider-shore: console on http://%s:%d/ (%s)\n", shown.c_str(), s.bound_port,
               s.auth ? "login required" : "loopback, no login");
  if (!c.port_file.empty()) write_file_atomically(c.port_file, std::to_string(s.bound_port) + "\n");
}

void ConsoleServer::stop() {
  Impl& s = *impl_;
  s.state.stop();  // wakes the event streams first, so the pool's threads can finish
  if (s.thread.joinable()) {
    s.server.stop();
    s.thread.join();
  }
}

unsigned ConsoleServer::port() const { return static_cast<unsigned>(impl_->bound_port); }

}  // namespace glider::shore::web
