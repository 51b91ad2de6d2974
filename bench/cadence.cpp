// Cadence of the frame clock on a pseudo-terminal: the bridge's run loop
// (Bridge + SerialLink, the real code path) against a plain absolute-sleep
// loop writing the same frame, both measured in the same run by a reader
// that stamps every frame as it arrives.
//   andros_bench_cadence [SECONDS]   (default 30)
#include <fcntl.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include <spdlog/spdlog.h>

#include "andros/base/clock.hpp"
#include "andros/base/shutdown_request.hpp"
#include "andros/link/serial_link.hpp"
#include "andros/run/bridge.hpp"
#include "bench_util.hpp"
#include "support/frame_doubles.hpp"

namespace {

using namespace andros;

constexpr int kRate = 25;
constexpr double kPeriodMs = static_cast<double>(kMsPerSecond) / kRate;

protocol::DataBytes neutral_frame() {
  protocol::ControlState s;
  s[protocol::signal_id("drive")] = protocol::kNeutralCentre;
  s[protocol::signal_id("pivot")] = protocol::kNeutralCentre;
  s[protocol::signal_id("battery")] = 0xCC;
  return protocol::FrameBuilder(0x01).build(s);
}

/// Its mapping names no deadman and no stop button (the tests' double): never enabled, nothing stops.
class FixedFrames final : public testing::WithoutStops {
 public:
  run::Step step(const input::InputState&, std::int64_t, bool) override { return {neutral_frame(), {}}; }
  protocol::DataBytes neutral() const override { return neutral_frame(); }
  void rebase(const input::InputState&) override {}
};

class Idle final : public input::InputSource {
 public:
  void pump(input::TickInput&, std::int64_t) override {}
  bool finished(std::int64_t) const override { return false; }
};

struct Result {
  std::size_t frames = 0;
  double median_ms = 0;
  double p99_dev_ms = 0;
  double max_dev_ms = 0;
  double drift_ms_per_min = 0;
};

Result analyse(const std::vector<bench::Arrival>& a) {
  Result r;
  r.frames = a.size();
  if (a.size() < 3) return r;
  std::vector<double> periods;
  std::vector<double> devs;
  for (std::size_t i = 1; i < a.size(); ++i) {
    const double p = static_cast<double>(a[i].t_ns - a[i - 1].t_ns) / kNsPerMs;
    periods.push_back(p);
    devs.push_back(std::abs(p - kPeriodMs));
  }
  r.median_ms = bench::quantile(periods, 0.5);
  r.p99_dev_ms = bench::quantile(devs, 0.99);
  r.max_dev_ms = devs.back();  // sorted by quantile()
  // Drift: the slope of each frame's offset from its ideal tick time.
  double st = 0, so = 0, stt = 0, sto = 0;
  const double n = static_cast<double>(a.size());
  for (const auto& f : a) {
    const double t = static_cast<double>(f.t_ns - a[0].t_ns) / kNsPerMs;
    const double off = t - std::round(t / kPeriodMs) * kPeriodMs;
    st += t;
    so += off;
    stt += t * t;
    sto += t * off;
  }
  const double slope = (n * sto - st * so) / (n * stt - st * st);  // ms per ms
  r.drift_ms_per_min = slope * 60'000.0;
  return r;
}

void print_row(const char* name, const Result& r) {
  std::printf("| %-34s | %6zu | %10.3f ms | %10.3f ms | %10.3f ms | %+9.3f ms/min |\n", name, r.frames, r.median_ms,
              r.p99_dev_ms, r.max_dev_ms, r.drift_ms_per_min);
}

}  // namespace

int main(int argc, char** argv) {
  const int seconds = argc > 1 ? std::atoi(argv[1]) : 30;
  spdlog::set_level(spdlog::level::warn);
  auto bridge_pty = link::open_pty_pair();
  auto plain_pty = link::open_pty_pair();
  Idle input;
  FixedFrames frames;
  link::SerialLink link(bridge_pty.path, 9600);
  RealClock clock;
  run::Bridge bridge(clock, input, frames, link,
                     run::BridgeOptions{.rate_millihertz = kRate * timing::kMillihertzPerHz, .rules = {false, 0x01}});
  UniqueFd plain_fd(open(plain_pty.path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC));
  link::configure_raw_8n1(plain_fd.get(), 9600);
  const protocol::Frame frame = protocol::encode(neutral_frame());

  const std::int64_t stop_ns = monotonic_ns() + std::int64_t{seconds} * kNsPerSecond;
  ShutdownRequest stop;
  std::vector<bench::Arrival> bridge_got;
  std::vector<bench::Arrival> plain_got;
  // When each loop's write() returned: the clock itself, before the pty's
  // delivery (a kernel worker) adds its own latency to the arrival times.
  std::vector<bench::Arrival> bridge_wrote;
  std::vector<bench::Arrival> plain_wrote;
  bridge_wrote.reserve(static_cast<std::size_t>(seconds + 1) * kRate);
  plain_wrote.reserve(static_cast<std::size_t>(seconds + 1) * kRate);
  std::thread bridge_reader([&] { bridge_got = bench::read_arrivals(bridge_pty.master.get(), stop_ns); });
  std::thread plain_reader([&] { plain_got = bench::read_arrivals(plain_pty.master.get(), stop_ns); });
  std::thread plain_loop([&] {
    // Half a period out of phase with the bridge, so that the two loops (and
    // their readers) never wake at the same instant and queue for a core.
    const std::int64_t t0 = monotonic_ns() + 500'000'000 / kRate;
    const TickGrid grid(kNsPerSecond, kRate);
    for (std::int64_t k = 0; !stop.requested(); ++k) {
      andros::sleep_until_ns_uninterrupted(t0 + grid.tick_ns(k));
      [[maybe_unused]] const auto n = write(plain_fd.get(), frame.data(), frame.size());
      if (monotonic_ns() < stop_ns) plain_wrote.push_back({monotonic_ns(), {}});
    }
  });
  std::thread bridge_loop([&] {
    bridge.run([&] { return stop.requested(); },
               [&](const run::TickReport& r) {
                 if (!r.shutting_down() && monotonic_ns() < stop_ns) bridge_wrote.push_back({monotonic_ns(), {}});
               });
  });
  bridge_reader.join();
  plain_reader.join();
  stop.raise();
  plain_loop.join();
  bridge_loop.join();

  const auto b = analyse(bridge_got);
  const auto p = analyse(plain_got);
  std::printf(
      "Cadence on a pseudo-terminal, %d Hz, %d s (both loops in the same run; frames stamped on\n"
      "arrival at the pty's far end, and, below, when each loop's write() returned)\n\n",
      kRate, seconds);
  std::printf("| %-34s | %6s | %13s | %13s | %13s | %16s |\n", "loop", "frames", "median period", "p99 |dev|",
              "max |dev|", "drift");
  std::printf("|%s|--------|---------------|---------------|---------------|------------------|\n",
              std::string(36, '-').c_str());
  print_row("bridge (Bridge + SerialLink)", b);
  print_row("plain clock_nanosleep loop", p);
  print_row("bridge, at write()", analyse(bridge_wrote));
  print_row("plain loop, at write()", analyse(plain_wrote));
  const bool median_ok = std::abs(b.median_ms - kPeriodMs) < 0.5;
  const bool p99_ok = b.p99_dev_ms <= p.p99_dev_ms + 1.0;
  const bool drift_ok = std::abs(b.drift_ms_per_min) < 5.0;
  std::printf("\ntargets: median 40 ms %s; p99 within 1 ms of the plain loop (%+.3f ms) %s; drift < 5 ms/min %s\n",
              median_ok ? "PASS" : "FAIL", b.p99_dev_ms - p.p99_dev_ms, p99_ok ? "PASS" : "FAIL",
              drift_ok ? "PASS" : "FAIL");
  return median_ok && p99_ok && drift_ok ? 0 : 1;
}
