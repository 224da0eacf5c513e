// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/modbus_link.hpp"

#include <modbus/modbus.h>
#include <sys/select.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace glider::hal_linux {
namespace {

// The connection itself is gone: close it, reconnect on the next attempt.
bool is_link_error(int error) {
  return error == ECONNRESET || error == EPIPE || error == EBADF || error == ECONNREFUSED || error == ENOTCONN ||
         error == EIO || error == ENXIO;
}

// The device understood and refused: asking again cannot help.
bool is_permanent(int error) { return error == EMBXILFUN || error == EMBXILADD || error == EMBXILVAL; }

void set_timeout(modbus_t* context, int (*setter)(modbus_t*, std::uint32_t, std::uint32_t), int ms) {
  setter(context, static_cast<std::uint32_t>(ms / 1000), static_cast<std::uint32_t>(ms % 1000) * 1000u);
}

}  // namespace

std::unique_ptr<ModbusLink> ModbusLink::open(const BusConfig& bus, std::string& warning, std::string& error) {
  warning.clear();
  error.clear();
  modbus_t* context = nullptr;
  if (bus.transport == Transport::kTcp) {
    context = modbus_new_tcp_pi(bus.host.c_str(), std::to_string(bus.port).c_str());
  } else {
    context = modbus_new_rtu(bus.device.c_str(), bus.baud, bus.parity, bus.data_bits, bus.stop_bits);
  }
  if (context == nullptr) {
    error = describe(bus) + ": " + modbus_strerror(errno);
    return nullptr;
  }
  // Recovery is ours (bounded): libmodbus' own link recovery sleeps and
  // reconnects inside a call, which would break the cycle budget.
  modbus_set_error_recovery(context, MODBUS_ERROR_RECOVERY_NONE);
  set_timeout(context, modbus_set_response_timeout, bus.response_timeout_ms);
  set_timeout(context, modbus_set_byte_timeout, bus.byte_timeout_ms);
  std::unique_ptr<ModbusLink> link(new ModbusLink(bus, context));
  if (link->connect() && link->serial_mode_refused_) {
    warning = describe(bus) + ": RS-485 mode not available (" + modbus_strerror(link->serial_mode_errno_) +
              "); continuing in the port's own mode";
  }
  return link;
}

ModbusLink::ModbusLink(const BusConfig& bus, _modbus* context)
    : bus_(bus),
      context_(context),
      // One attempt on a dead bus: the response timeout plus one byte timeout.
      attempt_cost_(std::chrono::milliseconds(bus.response_timeout_ms + bus.byte_timeout_ms)) {}

ModbusLink::~ModbusLink() {
  disconnect();
  modbus_free(context_);
}

bool ModbusLink::connect() noexcept {
  ++stats_.reconnects;
  // TCP: libmodbus connects non-blocking and waits at most the response
  // timeout. RTU: opening the device does not wait for anybody.
  if (modbus_connect(context_) == -1) {
    last_error_ = modbus_strerror(errno);
    return false;
  }
  connected_ = true;
  needs_flush_ = false;
  // On every (re)connect: a USB adapter that appeared late still gets it.
  // Needs a serial driver with RS-485 support (TIOCSRS485); a pty or an
  // adapter that switches direction itself answers ENOTTY. Not fatal.
  if (bus_.transport == Transport::kRtu && bus_.rs485) {
    serial_mode_refused_ = modbus_rtu_set_serial_mode(context_, MODBUS_RTU_RS485) == -1;
    if (serial_mode_refused_) serial_mode_errno_ = errno;
  }
  return true;
}

void ModbusLink::disconnect() noexcept {
  if (connected_) modbus_close(context_);
  connected_ = false;
}

void ModbusLink::begin_cycle() noexcept {
  window_start_ = Clock::now();
  window_deadline_ = window_start_ + std::chrono::milliseconds(bus_.cycle_budget_ms);
  window_open_ = true;
}

bool ModbusLink::fits_budget(Clock::time_point now) const noexcept { return now + attempt_cost_ <= window_deadline_; }

// RTU has no transaction id: a reply that comes after the timeout would be
// read as the answer to the next request (the same function and length for
// the other axis: a silently wrong position). So after a timeout wait, up to
// one more response timeout and never past the cycle budget, for the line
// to be quiet, discarding what arrives. (TCP matches transaction ids.)
void ModbusLink::drain_late_reply() noexcept {
  const int fd = modbus_get_socket(context_);
  if (fd < 0) return;
  auto deadline = std::min(window_deadline_, Clock::now() + std::chrono::milliseconds(bus_.response_timeout_ms));
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::microseconds>(deadline - Clock::now()).count();
    if (left <= 0) break;
    fd_set readable;
    FD_ZERO(&readable);
    FD_SET(fd, &readable);
    timeval wait{static_cast<time_t>(left / 1'000'000), static_cast<suseconds_t>(left % 1'000'000)};
    if (select(fd + 1, &readable, nullptr, nullptr, &wait) <= 0) break;
    std::uint8_t discard[64];
    if (read(fd, discard, sizeof discard) <= 0) break;
    // Bytes are still coming: the line is quiet one byte timeout after the last.
    deadline = std::min(window_deadline_, Clock::now() + std::chrono::milliseconds(bus_.byte_timeout_ms));
  }
}

template <typename Request>
bool ModbusLink::transact(int slave, Request&& request) noexcept {
  ++stats_.transactions;
  const Clock::time_point start = Clock::now();
  if (!window_open_ || start - window_start_ >= std::chrono::milliseconds(bus_.cycle_period_ms)) begin_cycle();
  for (int attempt = 0; attempt <= bus_.retries; ++attempt) {
    if (!fits_budget(Clock::now())) {
      ++stats_.budget_refusals;
      last_error_ = "cycle budget exhausted (earlier requests this cycle timed out)";
      break;
    }
    if (!connected_ && !connect()) continue;
    // After a failure, bytes of a late or garbled reply may still be
    // waiting; they must not be taken for the next answer.
    if (needs_flush_) modbus_flush(context_);
    modbus_set_slave(context_, slave);
    ++stats_.attempts;
    if (request() != -1) {
      needs_flush_ = false;
      return true;
    }
    const int error = errno;
    last_error_ = modbus_strerror(error);
    needs_flush_ = true;
    if (is_link_error(error)) disconnect();
    if (error == ETIMEDOUT && bus_.transport == Transport::kRtu) drain_late_reply();
    if (is_permanent(error)) break;
  }
  ++stats_.failed;
  return false;
}

bool ModbusLink::read_registers(int slave, int address, int count, std::uint16_t* out) noexcept {
  return transact(slave, [&] { return modbus_read_registers(context_, address, count, out); });
}

bool ModbusLink::write_registers(int slave, int address, int count, const std::uint16_t* values) noexcept {
  return transact(slave, [&] { return modbus_write_registers(context_, address, count, values); });
}

}  // namespace glider::hal_linux
