// The flight recorder's cost (docs/recording.md), three ways of keeping the
// frames: a record when the frame (or its result, or the tick's place)
// changes, what `run` does; a record for every frame; a SHA-256 digest of
// each second's frames. For each: the time the loop's thread spends per tick
// (the recorder's observe and push), the process's CPU per tick with the
// writer thread's hashing and writing, and the session's size per hour.
// Two drives: the stick moving on every tick (the worst case), and at rest.
//   andros_bench_recorder [TICKS]    (default 100000: 67 minutes at 25 Hz)
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "andros/base/clock.hpp"
#include "andros/base/sha256.hpp"
#include "andros/record/recorder.hpp"

namespace {

using namespace andros;

double cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

enum class Way { kChanges, kEveryFrame, kDigest };
const char* name(Way w) {
  switch (w) {
    case Way::kChanges: return "a record per change (run's)";
    case Way::kEveryFrame: return "a record per frame";
    case Way::kDigest: return "a digest per second";
  }
  return "?";
}

void measure(Way way, bool moving, std::int64_t ticks) {
  const auto path = std::filesystem::temp_directory_path() / ("andros-bench-" + std::to_string(getpid()) + ".session");
  std::filesystem::remove(path);
  std::vector<double> loop_ns;
  loop_ns.reserve(static_cast<std::size_t>(ticks));
  const double cpu0 = cpu_s();
  {
    record::SessionWriter writer(std::make_unique<record::FileRecordSink>(path.string()));
    record::Recorder recorder(writer);
    Sha256 digest;
    run::TickReport r;
    r.state = run::OpState::kEnabled;
    r.result = link::SendResult::kSent;
    r.data = {0x06, 0x00, 0x18, 0x20, 0x00, 0x90, 0x80, 0x80, 0, 0, 0, 0x01, 0, 0x20, 0xCC, 0x02};
    for (std::int64_t k = 0; k < ticks; ++k) {
      r.tick = k;
      r.t_ms = k * 40;
      if (moving) r.data[7] = static_cast<std::uint8_t>(129 + k % 126);
      const std::int64_t t0 = monotonic_ns();
      switch (way) {
        case Way::kChanges: recorder.observe(r); break;
        case Way::kEveryFrame: writer.push(record::payload::frame(r, 0)); break;
        case Way::kDigest: {
          const auto frame = protocol::encode(r.data);
          digest.update(std::string_view(reinterpret_cast<const char*>(frame.data()), frame.size()));
          if (k % 25 == 24) writer.push("digest " + std::to_string(r.t_ms) + " " + to_hex(digest.finish()));
          break;
        }
      }
      loop_ns.push_back(static_cast<double>(monotonic_ns() - t0));
      // The loop's pace, compressed: the writer wakes every 100 ms, so the
      // queue is given time to drain as it would have at 25 Hz.
      if (k % 1000 == 999) usleep(100'000);
    }
    writer.close(10'000);
    if (writer.dropped() + writer.lost() != 0)
      std::printf("(dropped %llu)\n", static_cast<unsigned long long>(writer.dropped()));
  }
  const double cpu = cpu_s() - cpu0;
  const auto bytes = std::filesystem::file_size(path);
  std::filesystem::remove(path);
  std::sort(loop_ns.begin(), loop_ns.end());
  double sum = 0;
  for (const double v : loop_ns) sum += v;
  const double hours = static_cast<double>(ticks) / 25.0 / 3600.0;
  std::printf("| %s | %s | %.0f ns | %.0f ns | %.2f us | %.1f MB |\n", name(way), moving ? "stick moving" : "at rest",
              sum / static_cast<double>(ticks), loop_ns[loop_ns.size() * 99 / 100],
              cpu * 1e6 / static_cast<double>(ticks), static_cast<double>(bytes) / 1e6 / hours);
}

}  // namespace

int main(int argc, char** argv) {
  const std::int64_t ticks = argc > 1 ? std::stoll(argv[1]) : 100'000;
  std::printf(
      "| frames kept as | drive | loop's thread, mean per tick | p99 | CPU per tick, writer included | session per "
      "hour at 25 Hz |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const bool moving : {true, false}) {
    for (const Way way : {Way::kChanges, Way::kEveryFrame, Way::kDigest}) measure(way, moving, ticks);
  }
  return 0;
}
