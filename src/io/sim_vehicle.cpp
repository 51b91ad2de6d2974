#include "andros/io/sim_vehicle.hpp"

#include <poll.h>
#include <pty.h>
#include <sys/eventfd.h>

#include <cerrno>
#include <cstring>

#include "andros/error.hpp"
#include "andros/io/link.hpp"
#include "andros/io/serial_link.hpp"

namespace andros::io {

SimVehicle::SimVehicle(std::uint8_t expected_code) : view_(expected_code) {
  int master = -1;
  int slave = -1;
  char name[256] = {};
  if (openpty(&master, &slave, name, nullptr, nullptr) != 0) {
    throw RuntimeError(std::string("sim: cannot open a pseudo-terminal: ") + std::strerror(errno));
  }
  master_.reset(master);
  slave_.reset(slave);
  path_ = name;
  // Raw on both sides: the line discipline must pass the bytes untouched.
  configure_raw_8n1(master_.get(), 9600);
  wake_.reset(eventfd(0, EFD_CLOEXEC));
  if (!wake_) throw RuntimeError(std::string("sim: eventfd: ") + std::strerror(errno));
}

SimVehicle::~SimVehicle() {
  if (thread_.joinable()) {
    const std::uint64_t one = 1;
    [[maybe_unused]] const auto n = write(wake_.get(), &one, sizeof one);
    thread_.join();
  }
}

void SimVehicle::start() { thread_ = std::thread([this] { run(); }); }

VehicleSnapshot SimVehicle::snapshot() const {
  const std::lock_guard lock(mutex_);
  return view_.snapshot(monotonic_ns());
}

void SimVehicle::run() {
  std::uint8_t buf[512];
  pollfd fds[2] = {{master_.get(), POLLIN, 0}, {wake_.get(), POLLIN, 0}};
  while (true) {
    if (poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      return;
    }
    if (fds[1].revents != 0) return;
    if ((fds[0].revents & POLLIN) == 0) continue;
    const auto n = read(master_.get(), buf, sizeof buf);
    if (n <= 0) continue;
    const auto now = monotonic_ns();
    const std::lock_guard lock(mutex_);
    view_.push(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)), now);
  }
}

}  // namespace andros::io
