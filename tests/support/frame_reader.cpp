#include "support/frame_reader.hpp"

#include <poll.h>
#include <unistd.h>

#include <algorithm>

#include "andros/base/clock.hpp"
#include "andros/link/link.hpp"
#include "andros/protocol/decoder.hpp"

namespace andros::test {

std::vector<protocol::DecodedFrame> FrameReader::next(std::size_t count, int timeout_ms) {
  const std::int64_t deadline = monotonic_ns() + std::int64_t{timeout_ms} * kNsPerMs;
  std::uint8_t buf[512];
  while (pending_.size() < count) {
    const auto left_ms = (deadline - monotonic_ns()) / kNsPerMs;
    if (left_ms <= 0) break;
    pollfd p{fd_, POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(left_ms)) <= 0) continue;
    const auto n = read(fd_, buf, sizeof buf);
    if (n <= 0) break;
    decoder_.push(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)),
                  [&](const protocol::DecodedFrame& f) { pending_.push_back(f); });
  }
  const auto take = std::min(count, pending_.size());
  std::vector<protocol::DecodedFrame> out(pending_.begin(), pending_.begin() + static_cast<long>(take));
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<long>(take));
  return out;
}

}  // namespace andros::test
