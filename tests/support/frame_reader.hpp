#pragma once
// Test helper: bounded reads of whole frames from a pty's far end or a socket.

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "andros/protocol/decoder.hpp"
#include "andros/protocol/frame.hpp"

namespace andros::test {

/// Decodes the frames arriving on fd, with bounded waits.
class FrameReader {
 public:
  explicit FrameReader(int fd) : fd_(fd) {}
  /// Waits at most timeout_ms for `count` more frames; returns those that came.
  std::vector<protocol::DecodedFrame> next(std::size_t count, int timeout_ms);

 private:
  int fd_;
  protocol::Decoder decoder_;
  std::deque<protocol::DecodedFrame> pending_;
};

}  // namespace andros::test
