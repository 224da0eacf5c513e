// SPDX-License-Identifier: Apache-2.0
// Load on the console (docs/console.md, "Load"): N page clients, each a thread
// with its own keep-alive connection requesting the pages and their JSON in
// turn as fast as answers come, and M event streams held open, for a bounded
// time; prints one JSON line: requests, errors, latency percentiles (ms),
// stream events received. Usage:
//   console_load --port P [--clients 200] [--streams 50] [--seconds 10] [--path /api/fleet]...
#include <httplib.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

struct Options {
  int port = 0, clients = 200, streams = 50;
  double seconds = 10.0;
  std::vector<std::string> paths;
};

bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    char* end = nullptr;
    const double number = std::strtod(value.c_str(), &end);
    const bool numeric = end != value.c_str() && *end == '\0' && number >= 0 && number <= 100000;
    if (key == "--path") {
      o.paths.push_back(value);
    } else if (numeric && key == "--port") {
      o.port = static_cast<int>(number);
    } else if (numeric && key == "--clients") {
      o.clients = static_cast<int>(number);
    } else if (numeric && key == "--streams") {
      o.streams = static_cast<int>(number);
    } else if (numeric && key == "--seconds" && number <= 600) {
      o.seconds = number;
    } else {
      std::fprintf(stderr, "console_load: bad option %s %s\n", key.c_str(), value.c_str());
      return false;
    }
  }
  if (o.paths.empty()) o.paths = {"/", "/api/fleet", "/glider/g00", "/api/gliders/g00"};
  return o.port > 0 && o.port < 65536 && o.clients >= 0 && o.streams >= 0;
}

double percentile(std::vector<double>& v, double p) {
  if (v.empty()) return 0.0;
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
  return v[k];
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    std::fprintf(stderr, "usage: console_load --port P [--clients N] [--streams M] [--seconds S] [--path P]...\n");
    return 2;
  }
  std::atomic<bool> stop{false};
  std::atomic<long> errors{0}, stream_events{0}, streams_open{0}, stream_errors{0};
  std::mutex mutex;
  std::vector<double> latencies_ms;

  std::vector<std::unique_ptr<httplib::Client>> stream_clients;
  std::vector<std::thread> threads;
  for (int s = 0; s < o.streams; ++s) {
    stream_clients.push_back(std::make_unique<httplib::Client>("127.0.0.1", o.port));
    httplib::Client* client = stream_clients.back().get();
    client->set_read_timeout(30, 0);
    threads.emplace_back([&, client] {
      bool counted = false;
      const auto result = client->Get("/api/events", [&](const char* data, std::size_t length) {
        if (!counted) {
          counted = true;
          ++streams_open;
        }
        const std::string chunk(data, length);
        for (std::size_t at = chunk.find("event: change"); at != std::string::npos;
             at = chunk.find("event: change", at + 1)) {
          ++stream_events;
        }
        return !stop.load();
      });
      if (!stop && (!result || result->status != 200)) ++stream_errors;
    });
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // streams open first, as browsers keep them
  const auto start = Clock::now();
  const auto end = start + std::chrono::duration<double>(o.seconds);
  for (int c = 0; c < o.clients; ++c) {
    threads.emplace_back([&, c] {
      httplib::Client client("127.0.0.1", o.port);
      client.set_keep_alive(true);
      client.set_tcp_nodelay(true);  // as browsers do
      client.set_read_timeout(10, 0);
      std::vector<double> mine;
      std::size_t k = static_cast<std::size_t>(c);
      while (Clock::now() < end) {
        const std::string& path = o.paths[k++ % o.paths.size()];
        const auto t0 = Clock::now();
        const auto result = client.Get(path);
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        if (!result || result->status != 200) {
          ++errors;
        } else {
          mine.push_back(ms);
        }
      }
      std::lock_guard<std::mutex> lock(mutex);
      latencies_ms.insert(latencies_ms.end(), mine.begin(), mine.end());
    });
  }
  for (std::size_t i = static_cast<std::size_t>(o.streams); i < threads.size(); ++i) threads[i].join();
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  stop = true;
  for (auto& client : stream_clients) client->stop();
  for (int s = 0; s < o.streams; ++s) threads[static_cast<std::size_t>(s)].join();
  const std::size_t n = latencies_ms.size();
  const double p50 = percentile(latencies_ms, 0.50), p90 = percentile(latencies_ms, 0.90),
               p99 = percentile(latencies_ms, 0.99),
               max = n ? *std::max_element(latencies_ms.begin(), latencies_ms.end()) : 0.0;
  std::printf(
      "{\"clients\":%d,\"streams\":%d,\"seconds\":%.2f,\"requests\":%zu,\"requests_per_s\":%.0f,\"errors\":%ld,"
      "\"p50_ms\":%.2f,\"p90_ms\":%.2f,\"p99_ms\":%.2f,\"max_ms\":%.2f,\"streams_open\":%ld,\"stream_errors\":%ld,"
      "\"stream_events\":%ld}\n",
      o.clients, o.streams, wall, n, static_cast<double>(n) / wall, errors.load(), p50, p90, p99, max,
      streams_open.load(), stream_errors.load(), stream_events.load());
  return 0;
}
