#pragma once
/// A pseudo-terminal pair standing in for a serial line: the simulated
/// vehicle's, and the tests' and benchmarks' stand-in for a USB adapter.

#include <string>

#include "andros/base/unique_fd.hpp"

namespace andros::link {

struct PtyPair {
  UniqueFd master;   ///< the far (vehicle's) end
  UniqueFd slave;    ///< the near end; whoever holds it open keeps the master from hanging up
  std::string path;  ///< the near end's path, to open like a serial device
};

/// Opens a pair with the master raw (bytes pass untouched) and both ends
/// close-on-exec: a child process holding an inherited master would keep an
/// "unplugged" pty alive. Throws RuntimeError.
PtyPair open_pty_pair();

}  // namespace andros::link
