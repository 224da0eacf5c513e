// SPDX-License-Identifier: Apache-2.0
#include "shore_server.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <csignal>

#include <atomic>
#include <utility>  // Boost 1.74's asio uses std::exchange without it

#include <boost/asio.hpp>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "after_surfacing.hpp"
#include "after_surfacing_queue.hpp"
#include "glider_folders.hpp"
#include "shore_session.hpp"

namespace glider::shore {
namespace {

using boost::asio::ip::tcp;

// Gliders whose health and forecast run side by side (each takes about a
// second of one core); one glider's runs are always in turn.
constexpr int kAfterSurfacingWorkers = 2;
// On SIGTERM: how long queued health and forecasts may still run (systemd's
// default stop timeout is 90 s; the calls' own end takes up to 30 s).
constexpr double kAfterSurfacingDrainS = 30.0;

boost::asio::ip::address listen_address(const ShoreConfig& config) {
  boost::system::error_code error;
  const boost::asio::ip::address address = boost::asio::ip::make_address(config.listen_address, error);
  if (error) throw std::runtime_error("--listen " + config.listen_address + ": not an IPv4 or IPv6 address");
  return address;
}

class Server {
 public:
  Server(const ShoreConfig& config, boost::asio::io_context& io, AfterSurfacingQueue& after)
      : config_(config),
        after_(after),
        acceptor_(io, tcp::endpoint(listen_address(config), static_cast<unsigned short>(config.port))) {}

  unsigned short port() const { return acceptor_.local_endpoint().port(); }
  // Nor may a child keep the listening port.
  void close_on_exec() { ::fcntl(acceptor_.native_handle(), F_SETFD, FD_CLOEXEC); }

  void accept() {
    acceptor_.async_accept([this](const boost::system::error_code& error, tcp::socket socket) {
      if (error) {
        if (!stop_) accept();
        return;
      }
      start_call(std::move(socket));
      accept();
    });
  }

  void stop() {
    stop_ = true;
    boost::system::error_code ignored;
    acceptor_.close(ignored);
  }

  // Waits (bounded) for the calls in progress to end after stop().
  void wait_for_calls() {
    std::unique_lock<std::mutex> lock(mutex_);
    calls_done_.wait_for(lock, std::chrono::seconds(30), [this] { return active_ == 0; });
  }

 private:
  void start_call(tcp::socket socket) {
    boost::system::error_code error;
    const tcp::endpoint remote = socket.remote_endpoint(error);
    const std::string peer = error ? "unknown" : remote.address().to_string() + ":" + std::to_string(remote.port());
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (active_ >= config_.max_calls) {
        std::fprintf(stderr, "glider-shore: call from %s refused: %d calls in progress (--max-calls)\n", peer.c_str(),
                     active_);
        return;  // the socket closes here
      }
      ++active_;
    }
    // The call owns a plain descriptor: its reads, writes and the lrzsz
    // children's pipes all go through poll(2) with deadlines.
    // Close-on-exec: an lrzsz child of another call must not hold this
    // connection open after this call has ended it.
    const int fd = ::fcntl(socket.native_handle(), F_DUPFD_CLOEXEC, 0);
    socket.close(error);
    if (fd < 0) {
      std::fprintf(stderr, "glider-shore: call from %s dropped: no file descriptor left\n", peer.c_str());
      call_ended();
      return;
    }
    std::fprintf(stderr, "glider-shore: call from %s\n", peer.c_str());
    try {
      std::thread([this, fd, peer] {
        serve_call(fd, peer, config_, stop_, after_);
        std::fprintf(stderr, "glider-shore: call from %s ended\n", peer.c_str());
        call_ended();
      }).detach();
    } catch (const std::system_error& failure) {
      std::fprintf(stderr, "glider-shore: call from %s dropped: %s\n", peer.c_str(), failure.what());
      ::close(fd);
      call_ended();
    }
  }

  void call_ended() {
    std::lock_guard<std::mutex> lock(mutex_);
    --active_;
    calls_done_.notify_all();
  }

  const ShoreConfig& config_;
  AfterSurfacingQueue& after_;
  tcp::acceptor acceptor_;
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::condition_variable calls_done_;
  int active_ = 0;
};

}  // namespace

void serve_forever(const ShoreConfig& config, const std::string& port_file) {
  // A Zmodem child that exits while the shore still writes to its stdin must
  // give EPIPE, not kill the shore and every other call.
  ::signal(SIGPIPE, SIG_IGN);
  std::filesystem::create_directories(config.root);
  boost::asio::io_context io;
  // Declared before the server: the calls it serves queue work on it.
  AfterSurfacingQueue after(kAfterSurfacingWorkers, after_surfacing);
  Server server(config, io, after);
  server.close_on_exec();
  boost::asio::signal_set signals(io, SIGINT, SIGTERM);
  signals.async_wait([&](const boost::system::error_code&, int) { server.stop(); });
  server.accept();
  std::fprintf(stderr, "glider-shore: listening on %s:%u, root %s\n", config.listen_address.c_str(), server.port(),
               config.root.c_str());
  if (!port_file.empty()) write_file_atomically(port_file, std::to_string(server.port()) + "\n");
  io.run();
  server.wait_for_calls();
  after.drain(kAfterSurfacingDrainS);
  std::fprintf(stderr, "glider-shore: stopped\n");
}

}  // namespace glider::shore
