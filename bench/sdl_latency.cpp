// Latency of the SDL input path, in process, with SDL's virtual pad:
//  - input change -> state: a stick moves at a random moment between ticks;
//    the next tick's pump() must show it (how long after the tick it did);
//  - tick -> frame bytes on a pty: the tick's state becomes a frame
//    (FrameBuilder, a trivial mapping: lefty -> drive) written to a pty's
//    slave; when are all 36 bytes readable on the master (FIONREAD)?
//  - controller loss -> disconnect: the tick after an unplug.
//   andros_bench_sdl_latency [TICKS]   (default 500, 20 s at 25 Hz)
#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include "andros/base/clock.hpp"
#include "andros/link/pty_pair.hpp"
#include "andros/link/serial_link.hpp"
#include "andros/protocol/frame.hpp"
#include "sdl_bench.hpp"

namespace {

using andros::kNsPerMs;
using andros::kNsPerSecond;
using andros::monotonic_ns;
using andros::bench::quantile;

constexpr std::int64_t kPeriodNs = 40'000'000;
constexpr auto kGrid = andros::TickGrid::every(kPeriodNs);
const andros::input::InputKey kLeftY{andros::input::InputKind::kPadAxis, SDL_CONTROLLER_AXIS_LEFTY};

void row(const char* name, const std::vector<double>& ms) {
  std::printf("| %-34s | %8.3f | %8.3f | %8.3f | %5zu |\n", name, quantile(ms, 0.5), quantile(ms, 0.99),
              quantile(ms, 1.0), ms.size());
}

/// The vehicle's side: waits (bounded) until a whole frame is readable on the
/// master, notes when, and consumes it. 0 when it never came.
std::int64_t wait_for_frame(int master) {
  const std::int64_t give_up = monotonic_ns() + kNsPerSecond;
  int queued = 0;
  while (monotonic_ns() < give_up) {
    if (ioctl(master, FIONREAD, &queued) == 0 && queued >= static_cast<int>(andros::protocol::kFrameSize)) {
      const std::int64_t at = monotonic_ns();
      std::uint8_t buf[andros::protocol::kFrameSize];
      if (read(master, buf, sizeof buf) != static_cast<ssize_t>(sizeof buf)) return 0;
      return at;
    }
    pollfd pfd{master, POLLIN, 0};
    poll(&pfd, 1, 1);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const long ticks = argc > 1 ? std::atol(argv[1]) : 500;
  andros::bench::PadRig rig;
  andros::input::SdlInput& input = rig.input;

  // The bridge's own pty stand-in; the near end raw, as SerialLink sets a port.
  const auto pty = andros::link::open_pty_pair();
  const int master = pty.master.get();
  const int slave = pty.slave.get();
  andros::link::configure_raw_8n1(slave, 9600);

  const andros::protocol::FrameBuilder builder(0x01);
  andros::input::TickInput pumped;
  const andros::input::InputState& state = pumped.state();
  std::mt19937 rng(42);
  std::uniform_int_distribution<std::int64_t> offset(2'000'000, kPeriodNs - 2'000'000);
  std::vector<double> set_to_state;
  std::vector<double> tick_to_state;
  std::vector<double> tick_to_bytes;
  std::vector<double> deadline_to_bytes;  // from the tick's nominal time: wake-up included
  std::vector<double> wake_lateness;      // the machine's share: a bare absolute sleep's lateness
  std::vector<std::int64_t> tick_at(static_cast<std::size_t>(ticks) + 1, 0);
  std::vector<std::int64_t> frame_done(static_cast<std::size_t>(ticks) + 1, 0);
  long missed = 0;
  const std::int64_t start = monotonic_ns() + kPeriodNs;
  for (long k = 0; k <= ticks; ++k) {
    const std::int64_t tick = start + kGrid.tick_ns(k);
    const auto value = static_cast<Sint16>(k % 2 == 0 ? 20000 + k : -20000 - k);
    andros::sleep_until_ns_uninterrupted(tick - offset(rng));
    const std::int64_t set = monotonic_ns();
    SDL_JoystickSetVirtualAxis(rig.pad, SDL_CONTROLLER_AXIS_LEFTY, value);
    andros::sleep_until_ns_uninterrupted(tick);
    tick_at[static_cast<std::size_t>(k)] = monotonic_ns();
    input.pump(pumped, k * 40);
    const std::int64_t seen = monotonic_ns();
    andros::protocol::ControlState control;
    control[andros::protocol::signal_id("drive")] =
        static_cast<std::uint8_t>(andros::protocol::kNeutralCentre + state.axis(kLeftY) / 256);
    const auto frame = andros::protocol::encode(builder.build(control));
    if (write(slave, frame.data(), frame.size()) != static_cast<ssize_t>(frame.size())) {
      std::perror("write");
      return 1;
    }
    frame_done[static_cast<std::size_t>(k)] = wait_for_frame(master);
    if (k == 0) continue;  // the connect's tick: initial state, not a change
    if (state.axis(kLeftY) != value) ++missed;
    set_to_state.push_back(static_cast<double>(seen - set) / kNsPerMs);
    tick_to_state.push_back(static_cast<double>(seen - tick_at[static_cast<std::size_t>(k)]) / kNsPerMs);
  }
  // Loss: unplug between ticks; how many ticks until the disconnect?
  const int index = [&] {
    for (int i = 0; i < SDL_NumJoysticks(); ++i) {
      if (SDL_JoystickGetDeviceInstanceID(i) == SDL_JoystickInstanceID(rig.pad)) return i;
    }
    return -1;
  }();
  SDL_JoystickClose(rig.pad);
  rig.pad = nullptr;
  SDL_JoystickDetachVirtual(index);
  int loss_ticks = 0;
  while (state.connected() && loss_ticks < 10) {
    ++loss_ticks;
    input.pump(pumped, (ticks + loss_ticks) * 40);
  }

  for (long k = 1; k <= ticks; ++k) {
    const auto done = frame_done[static_cast<std::size_t>(k)];
    if (done == 0) continue;
    tick_to_bytes.push_back(static_cast<double>(done - tick_at[static_cast<std::size_t>(k)]) / kNsPerMs);
    deadline_to_bytes.push_back(static_cast<double>(done - (start + kGrid.tick_ns(k))) / kNsPerMs);
    wake_lateness.push_back(static_cast<double>(tick_at[static_cast<std::size_t>(k)] - (start + kGrid.tick_ns(k))) /
                            kNsPerMs);
  }

  std::printf("| %-34s | %8s | %8s | %8s | %5s |\n", "latency (ms)", "median", "p99", "max", "n");
  std::printf("|------------------------------------|----------|----------|----------|-------|\n");
  row("axis set -> state (incl. wait)", set_to_state);
  row("tick -> state updated", tick_to_state);
  row("tick (nominal) -> woken", wake_lateness);
  row("tick (woken) -> 36 bytes on pty", tick_to_bytes);
  row("tick (nominal) -> 36 bytes on pty", deadline_to_bytes);
  const auto over =
      std::count_if(deadline_to_bytes.begin(), deadline_to_bytes.end(), [](double ms) { return ms > 1.0; });
  std::printf("\nframes on the pty more than 1 ms after their nominal tick: %ld of %zu\n", static_cast<long>(over),
              deadline_to_bytes.size());
  std::printf("changes not seen on the next tick: %ld of %ld\n", missed, ticks);
  std::printf("unplug -> disconnect: after %d tick(s)\n", loss_ticks);
  return missed == 0 && loss_ticks == 1 ? 0 : 1;
}
