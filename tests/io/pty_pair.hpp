#pragma once
// Test helpers: a pseudo-terminal pair standing in for a serial port, and
// bounded reads of whole frames from its far end.

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "andros/decoder.hpp"
#include "andros/frame.hpp"
#include "andros/io/unique_fd.hpp"

namespace andros::test {

struct PtyPair {
  PtyPair();
  io::UniqueFd master;  ///< the vehicle's end: read frames here
  io::UniqueFd slave;   ///< kept open so the master does not hang up
  std::string path;     ///< the slave's path, for the code under test
};

/// Decodes the frames arriving on fd, with bounded waits.
class FrameReader {
 public:
  explicit FrameReader(int fd) : fd_(fd) {}
  /// Waits at most timeout_ms for `count` more frames; returns those that came.
  std::vector<DecodedFrame> next(std::size_t count, int timeout_ms);

 private:
  int fd_;
  Decoder decoder_;
  std::deque<DecodedFrame> pending_;
};

}  // namespace andros::test
