// Cost of reading the controller at 25 Hz: CPU share of one core and peak
// RSS, for pump() every 40 ms on absolute time with a pad attached, against
// the same loop with no pump.
//   andros_bench_sdl_cost [SECONDS]   (default 20 per phase)
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "sdl_bench.hpp"

namespace {

using andros::kNsPerSecond;
using andros::monotonic_ns;

constexpr std::int64_t kAxisValues = andros::input::kAxisMax - andros::input::kAxisMin + 1;

struct Phase {
  double wall_s = 0;
  double cpu_s = 0;
  long ticks = 0;
};

double cpu_seconds() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
         static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec) / 1e6;
}

template <typename Work>
Phase run_phase(double seconds, Work&& work) {
  constexpr auto kGrid = andros::TickGrid::every(40 * andros::kNsPerMs);
  const long ticks = static_cast<long>(seconds * 25);
  const double cpu0 = cpu_seconds();
  const std::int64_t start = monotonic_ns();
  for (long k = 1; k <= ticks; ++k) {
    andros::sleep_until_ns_uninterrupted(start + kGrid.tick_ns(k));
    work(k * 40);
  }
  return Phase{static_cast<double>(monotonic_ns() - start) / kNsPerSecond, cpu_seconds() - cpu0, ticks};
}

void print(const char* name, const Phase& p) {
  std::printf("| %-28s | %7.1f | %8.3f | %9.3f %% | %6ld |\n", name, p.wall_s, p.cpu_s, 100.0 * p.cpu_s / p.wall_s,
              p.ticks);
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 20.0;
  andros::bench::PadRig rig;
  andros::input::TickInput tick;
  const andros::input::InputState& state = tick.state();

  const Phase idle = run_phase(seconds, [](std::int64_t) {});
  const Phase pumped = run_phase(seconds, [&](std::int64_t t) { rig.input.pump(tick, t); });
  // The operator holding a stick that moves every tick.
  const Phase moving = run_phase(seconds, [&](std::int64_t t) {
    SDL_JoystickSetVirtualAxis(rig.pad, SDL_CONTROLLER_AXIS_LEFTY,
                               static_cast<Sint16>((t * 97) % kAxisValues + andros::input::kAxisMin));
    rig.input.pump(tick, t);
  });
  if (!state.connected()) {
    std::fprintf(stderr, "the virtual pad never connected\n");
    return 1;
  }
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::printf("| %-28s | %7s | %8s | %11s | %6s |\n", "25 Hz loop", "wall s", "cpu s", "one core", "ticks");
  std::printf("|------------------------------|---------|----------|-------------|--------|\n");
  print("absolute sleep only", idle);
  print("pump(), pad at rest", pumped);
  print("pump(), stick moving", moving);
  std::printf("\npump() cost beyond the bare loop: %.3f %% (at rest), %.3f %% (moving) of one core\n",
              100.0 * (pumped.cpu_s - idle.cpu_s) / pumped.wall_s, 100.0 * (moving.cpu_s - idle.cpu_s) / moving.wall_s);
  std::printf("peak RSS: %.1f MB\n", static_cast<double>(ru.ru_maxrss) / 1024.0);
  return 0;
}
