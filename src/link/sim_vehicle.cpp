#include "andros/link/sim_vehicle.hpp"

#include <poll.h>
#include <pthread.h>
#include <termios.h>

#include "andros/base/clock.hpp"
#include "andros/link/link.hpp"
#include "andros/link/pty_pair.hpp"

namespace andros::link {

SimVehicle::SimVehicle(std::uint8_t expected_code) : view_(expected_code) {
  auto pty = open_pty_pair();
  master_ = std::move(pty.master);
  slave_ = std::move(pty.slave);
  // Wake the vehicle once a frame, not once a chunk: in raw mode the line
  // discipline reports the master readable only when VMIN bytes are there.
  termios tio{};
  if (tcgetattr(master_.get(), &tio) == 0) {
    tio.c_cc[VMIN] = protocol::kFrameSize;
    tcsetattr(master_.get(), TCSANOW, &tio);
  }
  path_ = std::move(pty.path);
}

SimVehicle::~SimVehicle() { stop(); }

void SimVehicle::stop() {
  if (!thread_.joinable()) return;
  stop_.raise();
  thread_.join();
}

void SimVehicle::start() {
  thread_ = std::thread([this] { run(); });
  pthread_setname_np(thread_.native_handle(), "andros-sim");
}

VehicleStatus SimVehicle::status() const {
  const std::lock_guard lock(mutex_);
  return view_.status(monotonic_ns());
}

bool SimVehicle::read_ready() {
  std::uint8_t buf[512];
  const auto n = read(master_.get(), buf, sizeof buf);
  if (n <= 0) return false;
  const auto now = monotonic_ns();
  const std::lock_guard lock(mutex_);
  view_.push(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)), now);
  return true;
}

void SimVehicle::run() {
  while (stop_.wait_readable(master_.get(), kNoDeadline)) read_ready();
  // Stopping: the bridge has drained its side; take in the last frames.
  pollfd last{master_.get(), POLLIN, 0};
  while (poll(&last, 1, 0) == 1 && (last.revents & POLLIN) != 0 && read_ready()) {
  }
}

}  // namespace andros::link
