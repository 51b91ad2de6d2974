#pragma once
// What the live-bridge benchmarks share: pseudo-terminals, a reader that
// timestamps every frame as it arrives, child processes, and percentiles.

#include <sys/resource.h>
#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

#include "andros/link/pty_pair.hpp"
#include "andros/protocol/decoder.hpp"

namespace andros::bench {

struct Arrival {
  std::int64_t t_ns;
  protocol::DataBytes data;
};

/// Reads frames from fd until stop_ns (monotonic), `max_frames`, or (with a
/// pid) that child's exit, which is left for wait_child to collect; each
/// frame is stamped when its last byte is read.
std::vector<Arrival> read_arrivals(int fd, std::int64_t stop_ns, std::size_t max_frames = SIZE_MAX,
                                   pid_t until_exit = 0);

/// Starts argv (stdout and stderr to /dev/null); returns its pid.
pid_t spawn(const std::vector<std::string>& argv);
/// Waits for pid; fills usage; returns the exit status (or -1).
int wait_child(pid_t pid, rusage* usage);

/// The q-quantile (0..1) of values (sorted in place).
double quantile(std::vector<double>& values, double q);

/// `BIN run --port PORT --input SCRIPT` as a child process, the script
/// written to a temporary file (removed with this). With no port given, the
/// port is a pty of its own, `pty`, whose master the benchmark reads.
struct BridgeProcess {
  BridgeProcess(const std::string& bin, const std::string& script_text, const std::string& port = {});
  ~BridgeProcess();
  BridgeProcess(const BridgeProcess&) = delete;
  BridgeProcess& operator=(const BridgeProcess&) = delete;

  link::PtyPair pty;
  std::string script;
  std::int64_t t0 = 0;  ///< monotonic ns just before the fork
  pid_t pid = -1;
};

}  // namespace andros::bench
