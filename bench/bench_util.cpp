#include "bench_util.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "andros/base/clock.hpp"
#include "andros/link/link.hpp"

namespace andros::bench {

namespace {

/// True once the child has exited, without collecting it.
bool exited(pid_t pid) {
  siginfo_t info{};
  return waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid;
}

}  // namespace

std::vector<Arrival> read_arrivals(int fd, std::int64_t stop_ns, std::size_t max_frames, pid_t until_exit) {
  protocol::Decoder decoder;
  std::vector<Arrival> out;
  std::uint8_t buf[512];
  while (out.size() < max_frames) {
    const auto left_ms = (stop_ns - monotonic_ns()) / kNsPerMs;
    if (left_ms <= 0) break;
    pollfd p{fd, POLLIN, 0};
    // Short polls while waiting for a child's exit, so that its time is measured closely.
    const std::int64_t slice = until_exit > 0 ? 2 : 100;
    if (poll(&p, 1, static_cast<int>(std::min<std::int64_t>(left_ms, slice))) <= 0) {
      if (until_exit > 0 && exited(until_exit)) break;
      continue;
    }
    const auto n = read(fd, buf, sizeof buf);
    const auto now = monotonic_ns();
    if (n <= 0) continue;
    decoder.push(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)), [&](const protocol::DecodedFrame& f) {
      out.push_back({now, f.data});
    });
  }
  return out;
}

pid_t spawn(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    if (std::getenv("ANDROS_BENCH_VERBOSE") == nullptr) dup2(null, STDERR_FILENO);
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

int wait_child(pid_t pid, rusage* usage) {
  int status = 0;
  if (wait4(pid, &status, 0, usage) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

double quantile(std::vector<double>& values, double q) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const auto i = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5);
  return values[std::min(i, values.size() - 1)];
}

BridgeProcess::BridgeProcess(const std::string& bin, const std::string& script_text, const std::string& port)
    : pty(link::open_pty_pair()),
      script("/tmp/andros-bench-" + std::to_string(getpid()) + "-" + std::to_string(monotonic_ns()) + ".events") {
  std::ofstream(script) << script_text;
  t0 = monotonic_ns();
  pid = spawn({bin, "run", "--port", port.empty() ? pty.path : port, "--input", script});
}

BridgeProcess::~BridgeProcess() { std::remove(script.c_str()); }

}  // namespace andros::bench
