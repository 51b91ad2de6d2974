// The bridge as an operator runs it, one process per measurement:
//  - first frame: from fork() to the first whole frame on the pty;
//  - controller loss: which frame after a disconnect is the first neutral one;
//  - cost at 25 Hz: CPU (% of one core) and peak RSS of a run, on a pty the
//    benchmark reads, and with the built-in simulated vehicle in the process.
//   andros_bench_process BIN [COST_SECONDS]   (default 20)
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "andros/io/link.hpp"
#include "bench_util.hpp"

namespace {

using namespace andros;

constexpr int kStartRuns = 10;
constexpr double kPeriodMs = 40.0;

bool is_neutral(const DataBytes& d) { return d[7] == 128 && d[6] == 128 && (d[0] & 0x02) == 0; }

void first_frame(const std::string& bin) {
  const auto script = bench::temp_file("start.events", "0 connect pad\n200 end\n");
  std::vector<double> ms;
  for (int i = 0; i < kStartRuns; ++i) {
    bench::Pty pty;
    const auto t0 = io::monotonic_ns();
    const pid_t pid = bench::spawn({bin, "run", "--port", pty.path, "--input", script});
    const auto got = bench::read_arrivals(pty.master.get(), t0 + 3'000'000'000, 1);
    if (!got.empty()) ms.push_back(static_cast<double>(got[0].t_ns - t0) / 1e6);
    bench::read_arrivals(pty.master.get(), t0 + 3'000'000'000, SIZE_MAX, pid);  // let it finish
    bench::wait_child(pid, nullptr);
  }
  std::remove(script.c_str());
  const auto n = ms.size();
  const double med = bench::quantile(ms, 0.5);
  const double max = ms.empty() ? 0 : ms.back();
  std::printf("| first frame after start (%zu runs)  | median %.1f ms, max %.1f ms | < 150 ms | %s |\n", n, med,
              max, n == kStartRuns && max < 150 ? "PASS" : "FAIL");
}

void controller_loss(const std::string& bin) {
  // Deadman pressed fresh at 100 ms, full drive from 200 ms, the controller lost at 1010 ms.
  const auto script = bench::temp_file(
      "loss.events", "0 connect pad\n100 button leftshoulder 1\n200 axis lefty -32768\n1010 disconnect\n1200 end\n");
  bench::Pty pty;
  const auto t0 = io::monotonic_ns();
  const pid_t pid = bench::spawn({bin, "run", "--port", pty.path, "--input", script});
  const auto got = bench::read_arrivals(pty.master.get(), t0 + 5'000'000'000, 34);
  bench::wait_child(pid, nullptr);
  std::remove(script.c_str());
  // Frame k is tick k (t = 40k ms): the loss falls between tick 25 (1000) and 26 (1040).
  std::size_t first_neutral = 0;
  for (std::size_t k = 26; k < got.size(); ++k) {
    if (is_neutral(got[k].data)) {
      first_neutral = k;
      break;
    }
  }
  const bool drove = got.size() > 25 && !is_neutral(got[25].data);
  const double after_ms = first_neutral > 0
                              ? static_cast<double>(got[first_neutral].t_ns - got[0].t_ns) / 1e6 - 1010.0
                              : 0;
  std::printf("| controller loss to neutral          | tick %zu (t = %.0f ms) is neutral, %zu tick(s) after the loss; "
              "%.1f ms after it | next tick | %s |\n",
              first_neutral, static_cast<double>(first_neutral) * kPeriodMs, first_neutral - 25, after_ms,
              drove && first_neutral == 26 ? "PASS" : "FAIL");
}

void cost(const std::string& bin, int seconds, bool sim) {
  const auto script = bench::temp_file(
      "cost.events", "0 connect pad\n100 button leftshoulder 1\n200 axis lefty -20000\n" +
                         std::to_string(seconds * 1000) + " end\n");
  bench::Pty pty;
  const auto t0 = io::monotonic_ns();
  const pid_t pid = bench::spawn({bin, "run", "--port", sim ? "sim" : pty.path, "--input", script});
  if (!sim) bench::read_arrivals(pty.master.get(), t0 + std::int64_t{seconds + 5} * 1'000'000'000, SIZE_MAX, pid);
  rusage usage{};
  bench::wait_child(pid, &usage);
  const double wall = static_cast<double>(io::monotonic_ns() - t0) / 1e9;
  std::remove(script.c_str());
  const double cpu = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                     static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
  const double pct = 100.0 * cpu / wall;
  const double rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  std::printf("| cost at 25 Hz, %-20s | %.2f%% of a core (%.2f s CPU in %.1f s), peak RSS %.1f MB | < 0.5%%, < 12 MB | %s |\n",
              sim ? "--port sim" : "--port PTY", pct, cpu, wall, rss_mb,
              pct < 0.5 && rss_mb < 12 ? "PASS" : "FAIL");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: andros_bench_process BIN [COST_SECONDS]\n");
    return 2;
  }
  const std::string bin = argv[1];
  const int seconds = argc > 2 ? std::atoi(argv[2]) : 20;
  std::printf("The bridge as a process (%s), script input\n\n", bin.c_str());
  std::printf("| measure | result | target | |\n|---|---|---|---|\n");
  first_frame(bin);
  controller_loss(bin);
  cost(bin, seconds, false);
  cost(bin, seconds, true);
  return 0;
}
