// The idle cost of `andros-bridge run` beside the floor, in one run: the
// floor (bench/floor.c, a C loop sleeping to absolute deadlines and writing
// 36 bytes to a pty every 40 ms) and the bridge (`run --port PTY`, nothing
// changing on its input) run side by side, and for each process:
//  - p99 period deviation: |gap between two frames - 40 ms| at the pty's far end;
//  - CPU: its CPU-time clock (every thread, in ns) over the window, as % of
//    one core and per frame;
//  - wake-ups per second: voluntary context switches of every thread
//    (/proc/PID/task/*/status), and which threads they come from: a thread
//    that gave up its core (to sleep, or to wait on a poll or a lock) and
//    is woken again, what keeps a core from resting (powertop's count);
//  - preemptions per second: involuntary context switches, a thread that
//    was running put aside by the scheduler (a task woken on its core: the
//    pty's reader its own write woke, a kernel worker); shown beside the
//    wake-ups, never added to them: they wake nothing;
//  - RSS (VmRSS at the end of the window).
// Cases: the SDL input with no controller, with SDL's virtual pad attached
// (LD_PRELOAD of libandros_bench_virtual_pad.so, beside this binary), and an
// event script that connects a pad and then holds still; each without the
// status view (stdout /dev/null) and with it (stdout an 80x24 pty). The
// simulated vehicle is not used: only the bridge process is measured.
//   andros_bench_idle_cost BIN [SECONDS] [CASE...]   (default 20 s per case, every case)
#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "andros/base/clock.hpp"
#include "andros/link/pty_pair.hpp"
#include "bench_util.hpp"

namespace {

using namespace andros;

constexpr double kPeriodMs = 40.0;
constexpr int kWarmupMs = 3000;  ///< start-up (SDL_Init, the first screen) left out
// The goals of issue 18, against the floor measured in the same run.
constexpr double kCpuFactorGoal = 1.5;
constexpr double kWakeupsGoal = 30.0;
constexpr double kRssGoalMb = 9.0;

struct Case {
  const char* name;
  const char* input;  ///< "sdl", "pad" (sdl + the virtual pad) or "script"
  bool view;
};

constexpr Case kCases[] = {
    {"sdl", "sdl", false},     {"sdl+view", "sdl", true},   {"pad", "pad", false},
    {"pad+view", "pad", true}, {"script", "script", false}, {"script+view", "script", true},
};

/// One process's counters at one moment.
struct Sample {
  std::int64_t cpu_ns = 0;
  std::map<std::string, long> switches;  ///< voluntary, by thread: "TID name"
  long preemptions = 0;                  ///< involuntary, every thread
  double rss_mb = 0;
};

long status_field(const std::string& path, const char* field) {
  std::ifstream in(path);
  std::string line;
  const std::size_t n = std::strlen(field);
  while (std::getline(in, line)) {
    if (line.compare(0, n, field) == 0 && line.size() > n && line[n] == ':') return std::atol(line.c_str() + n + 1);
  }
  return 0;
}

Sample sample(pid_t pid) {
  Sample s;
  clockid_t clock{};
  timespec ts{};
  if (clock_getcpuclockid(pid, &clock) == 0 && clock_gettime(clock, &ts) == 0) {
    s.cpu_ns = std::int64_t{ts.tv_sec} * kNsPerSecond + ts.tv_nsec;
  }
  const std::string dir = "/proc/" + std::to_string(pid) + "/task";
  if (DIR* d = opendir(dir.c_str())) {
    while (const dirent* e = readdir(d)) {
      if (e->d_name[0] == '.') continue;
      const std::string task = dir + "/" + e->d_name;
      std::string name;
      std::getline(std::ifstream(task + "/comm"), name);
      s.switches[std::string(e->d_name) + " " + name] = status_field(task + "/status", "voluntary_ctxt_switches");
      s.preemptions += status_field(task + "/status", "nonvoluntary_ctxt_switches");
    }
    closedir(d);
  }
  s.rss_mb = static_cast<double>(status_field("/proc/" + std::to_string(pid) + "/status", "VmRSS")) / 1024.0;
  return s;
}

/// Frame arrivals on one pty master, stamped by the reader.
struct Arrivals {
  int fd = -1;
  std::size_t bytes = 0;
  std::vector<std::int64_t> t_ns;  ///< when each 36th byte arrived
};

/// Reads every pty master until `stop`: frames on the ports, anything on the
/// bridge's terminal (drained, as a terminal would).
void read_all(std::vector<Arrivals*> ports, int terminal, const std::atomic<bool>& stop) {
  std::vector<pollfd> fds;
  for (auto* p : ports) fds.push_back({p->fd, POLLIN, 0});
  if (terminal >= 0) fds.push_back({terminal, POLLIN, 0});
  std::uint8_t buf[4096];
  while (!stop) {
    if (poll(fds.data(), fds.size(), 100) <= 0) continue;
    const auto now = monotonic_ns();
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if ((fds[i].revents & POLLIN) == 0) continue;
      const auto n = read(fds[i].fd, buf, sizeof buf);
      if (n <= 0 || i >= ports.size()) continue;
      auto& a = *ports[i];
      const std::size_t before = a.bytes / 36;
      a.bytes += static_cast<std::size_t>(n);
      for (std::size_t k = before; k < a.bytes / 36; ++k) a.t_ns.push_back(now);
    }
  }
}

/// p99 of |period - 40 ms| over the frames that arrived in [from, to).
double p99_deviation(const std::vector<std::int64_t>& t, std::int64_t from, std::int64_t to) {
  std::vector<double> devs;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i - 1] < from || t[i] >= to) continue;
    devs.push_back(std::abs(static_cast<double>(t[i] - t[i - 1]) / 1e6 - kPeriodMs));
  }
  return bench::quantile(devs, 0.99);
}

std::size_t frames_in(const std::vector<std::int64_t>& t, std::int64_t from, std::int64_t to) {
  std::size_t n = 0;
  for (const auto x : t) n += x >= from && x < to ? 1 : 0;
  return n;
}

/// Starts argv in a session of its own with stdout on `out` (or /dev/null),
/// stderr on /dev/null, and env added.
pid_t start(const std::vector<std::string>& argv, const std::string& out, const std::vector<std::string>& env) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    setsid();  // a terminal given as stdout becomes its controlling one: the view is in the foreground
    const int null = open("/dev/null", O_RDWR);
    const int fd = out.empty() ? null : open(out.c_str(), O_RDWR);
    dup2(null, STDIN_FILENO);
    dup2(fd, STDOUT_FILENO);
    if (std::getenv("ANDROS_BENCH_VERBOSE") == nullptr) dup2(null, STDERR_FILENO);
    for (const auto& e : env) putenv(const_cast<char*>(e.c_str()));
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

struct Measured {
  double p99_ms = 0;
  double cpu_pct = 0;
  double us_per_frame = 0;
  double wakeups = 0;
  double preemptions = 0;
  double rss_mb = 0;
  std::size_t frames = 0;
  std::string threads;  ///< wake-ups per second by thread
};

Measured measure(const Sample& a, const Sample& b, const Arrivals& port, std::int64_t t0, std::int64_t t1) {
  const double seconds = static_cast<double>(t1 - t0) / 1e9;
  Measured m;
  m.frames = frames_in(port.t_ns, t0, t1);
  m.p99_ms = p99_deviation(port.t_ns, t0, t1);
  m.cpu_pct = 100.0 * static_cast<double>(b.cpu_ns - a.cpu_ns) / static_cast<double>(t1 - t0);
  m.us_per_frame = m.frames > 0 ? static_cast<double>(b.cpu_ns - a.cpu_ns) / 1e3 / static_cast<double>(m.frames) : 0;
  long total = 0;
  std::ostringstream threads;
  for (const auto& [task, n] : b.switches) {
    const auto it = a.switches.find(task);
    const long d = n - (it == a.switches.end() ? 0 : it->second);
    total += d;
    threads << (threads.tellp() > 0 ? ", " : "") << task.substr(task.find(' ') + 1) << " "
            << static_cast<double>(std::lround(static_cast<double>(d) / seconds * 10)) / 10.0 << "/s";
  }
  m.wakeups = static_cast<double>(total) / seconds;
  m.preemptions = static_cast<double>(b.preemptions - a.preemptions) / seconds;
  m.rss_mb = b.rss_mb;
  m.threads = threads.str();
  return m;
}

void row(const std::string& name, const Measured& m, const char* verdict) {
  std::printf("| %-26s | %6zu | %7.3f ms | %6.3f %% | %7.1f us | %7.1f | %9.1f | %5.1f MB | %s |\n", name.c_str(),
              m.frames, m.p99_ms, m.cpu_pct, m.us_per_frame, m.wakeups, m.preemptions, m.rss_mb, verdict);
}

std::string beside_self(const std::string& name) {
  std::string self(4096, '\0');
  const auto n = readlink("/proc/self/exe", self.data(), self.size());
  self.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  return self.substr(0, self.rfind('/') + 1) + name;
}

/// One case: the floor and the bridge side by side; false when it fails its goals.
bool run_case(const std::string& bin, const Case& c, int seconds, const std::string& script) {
  auto floor_pty = link::open_pty_pair();
  auto bridge_pty = link::open_pty_pair();
  std::optional<link::PtyPair> terminal;
  if (c.view) {
    terminal.emplace(link::open_pty_pair());
    const winsize size{24, 80, 0, 0};
    ioctl(terminal->master.get(), TIOCSWINSZ, &size);
  }
  Arrivals floor_frames{floor_pty.master.get(), 0, {}};
  Arrivals bridge_frames{bridge_pty.master.get(), 0, {}};
  std::atomic<bool> stop{false};
  std::thread reader(read_all, std::vector<Arrivals*>{&floor_frames, &bridge_frames},
                     terminal ? terminal->master.get() : -1, std::cref(stop));

  const pid_t floor = start({beside_self("andros_bench_floor"), floor_pty.path}, "", {});
  std::vector<std::string> env{"SDL_VIDEODRIVER=dummy", "TERM=xterm-256color"};
  if (std::strcmp(c.input, "pad") == 0) env.push_back("LD_PRELOAD=" + beside_self("libandros_bench_virtual_pad.so"));
  const std::string input = std::strcmp(c.input, "script") == 0 ? script : "sdl";
  const pid_t bridge =
      start({bin, "run", "--port", bridge_pty.path, "--input", input}, terminal ? terminal->path : "", env);

  sleep_until_ns_uninterrupted(monotonic_ns() + kWarmupMs * kNsPerMs);
  const Sample floor0 = sample(floor);
  const Sample bridge0 = sample(bridge);
  const std::int64_t t0 = monotonic_ns();
  sleep_until_ns_uninterrupted(t0 + std::int64_t{seconds} * kNsPerSecond);
  const Sample floor1 = sample(floor);
  const Sample bridge1 = sample(bridge);
  const std::int64_t t1 = monotonic_ns();

  kill(floor, SIGTERM);
  kill(bridge, SIGTERM);
  sleep_until_ns_uninterrupted(monotonic_ns() + 500 * kNsPerMs);  // the bridge's neutral frames, read
  stop = true;
  reader.join();
  bench::wait_child(floor, nullptr);
  const int status = bench::wait_child(bridge, nullptr);

  const Measured f = measure(floor0, floor1, floor_frames, t0, t1);
  const Measured b = measure(bridge0, bridge1, bridge_frames, t0, t1);
  const bool cpu_ok = b.cpu_pct <= kCpuFactorGoal * f.cpu_pct;
  const bool wake_ok = b.wakeups <= kWakeupsGoal;
  const bool rss_ok = b.rss_mb <= kRssGoalMb;
  const bool ran = status == 0 && b.frames > 0;
  std::string verdict = ran ? "" : "DID NOT RUN (exit " + std::to_string(status) + ") ";
  verdict += std::string("CPU x") + std::to_string(f.cpu_pct > 0 ? b.cpu_pct / f.cpu_pct : 0).substr(0, 4) +
             (cpu_ok ? " ok" : " OVER") + (wake_ok ? ", wake-ups ok" : ", wake-ups OVER") +
             (rss_ok ? ", RSS ok" : ", RSS OVER");
  row(std::string("floor (") + c.name + ")", f, "");
  row(std::string("run --input ") + c.name, b, verdict.c_str());
  std::printf("|   threads | | | | | %s | | | |\n", b.threads.c_str());
  return ran && cpu_ok && wake_ok && rss_ok;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: andros_bench_idle_cost BIN [SECONDS] [CASE...]\n");
    return 2;
  }
  const std::string bin = argv[1];
  const int seconds = argc > 2 ? std::atoi(argv[2]) : 20;
  std::vector<std::string> wanted(argv + std::min(argc, 3), argv + argc);
  // The controller connects at once and holds still: no input changes.
  const std::string script = "/tmp/andros-bench-idle-" + std::to_string(getpid()) + ".events";
  std::ofstream(script) << "0 connect pad\n" << (seconds + kWarmupMs / 1000 + 60) * 1000 << " end\n";

  std::printf(
      "Idle cost of `%s run --port PTY` beside the floor (bench/floor.c), %d s per case after %d s\n"
      "of start-up; nothing changes on the input. Goals (issue 18): CPU <= %.1fx the floor's,\n"
      "<= %.0f wake-ups/s (voluntary switches; preemptions shown apart), RSS <= %.0f MB.\n\n",
      bin.c_str(), seconds, kWarmupMs / 1000, kCpuFactorGoal, kWakeupsGoal, kRssGoalMb);
  std::printf("| %-26s | %6s | %10s | %8s | %10s | %7s | %9s | %8s | |\n", "process", "frames", "p99 |dev|", "CPU",
              "CPU/frame", "wake/s", "preempt/s", "RSS");
  std::printf(
      "|----------------------------|--------|------------|----------|------------|---------|-----------|----------|---"
      "|"
      "\n");
  bool all_ok = true;
  for (const auto& c : kCases) {
    if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), c.name) == wanted.end()) continue;
    all_ok = run_case(bin, c, seconds, script) && all_ok;
  }
  std::remove(script.c_str());
  return all_ok ? 0 : 1;
}
