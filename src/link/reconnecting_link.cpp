#include "andros/link/reconnecting_link.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "andros/base/clock.hpp"

namespace andros::link {

std::string_view to_string(LinkState state) { return state == LinkState::kUp ? "up" : "connecting"; }

ReconnectingLink::ReconnectingLink(std::string name, int min_retry_ms, int max_retry_ms, Clock* drain_clock)
    : drain_clock_(drain_clock != nullptr ? *drain_clock : real_clock_),
      name_(std::move(name)),
      min_retry_ms_(min_retry_ms),
      max_retry_ms_(max_retry_ms),
      retry_ms_(min_retry_ms) {}

long ReconnectingLink::write_bytes(const std::uint8_t* data, std::size_t size) {
  return ::write(fd_.get(), data, size);
}

int ReconnectingLink::backlog(std::int64_t /*now_ns*/, std::string& /*stalled*/) { return queued_bytes(); }

void ReconnectingLink::fail_open(const std::string& why, std::int64_t now_ns) {
  close_fd();
  if (why != detail_) spdlog::warn("link {}: cannot open: {}; retrying", name_, why);
  detail_ = why;
  next_attempt_ns_ = now_ns + static_cast<std::int64_t>(retry_ms_) * kNsPerMs;
  retry_ms_ = std::min(retry_ms_ * 2, max_retry_ms_);
}

void ReconnectingLink::lose(const std::string& why, std::int64_t now_ns) {
  // A device that opens but fails every write would otherwise log a loss and
  // a recovery five times a second: the same loss within a second of coming
  // up is not news.
  quiet_ = why == last_loss_ && now_ns - up_since_ns_ < kFlapNs;
  if (!quiet_) spdlog::warn("link {}: lost ({}); sending resumes when it is back", name_, why);
  last_loss_ = why;
  ++counters_.losses;
  close_fd();
  state_ = LinkState::kConnecting;
  detail_ = why;
  if (now_ns - up_since_ns_ >= kStableNs) retry_ms_ = min_retry_ms_;
  next_attempt_ns_ = now_ns + static_cast<std::int64_t>(retry_ms_) * kNsPerMs;
  retry_ms_ = std::min(retry_ms_ * 2, max_retry_ms_);
}

SendResult ReconnectingLink::send(const protocol::Frame& frame, std::int64_t now_ns) {
  if (state_ != LinkState::kUp) {
    if (now_ns < next_attempt_ns_) {
      ++counters_.down;
      return SendResult::kDown;
    }
    std::string why;
    const auto result = open_step(now_ns, why);
    if (result == OpenResult::kFailed) {
      fail_open(why, now_ns);
      ++counters_.down;
      return SendResult::kDown;
    }
    if (result == OpenResult::kPending) {
      ++counters_.down;
      return SendResult::kDown;
    }
    state_ = LinkState::kUp;
    detail_.clear();
    up_since_ns_ = now_ns;
    if (!quiet_) spdlog::info("link {}: up", name_);
  }

  std::string stalled;
  const int queued = backlog(now_ns, stalled);
  if (queued < 0 || !stalled.empty()) {
    lose(queued < 0 ? std::string(std::strerror(errno)) : stalled, now_ns);
    ++counters_.down;
    return SendResult::kDown;
  }
  if (queued > 0) {
    // The newest state wins: a frame queued behind another would reach the
    // vehicle late, so this tick is skipped instead.
    ++counters_.busy;
    return SendResult::kBusy;
  }
  const long n = write_bytes(frame.data(), frame.size());
  if (n == static_cast<long>(frame.size())) {
    ++counters_.sent;
    return SendResult::kSent;
  }
  if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) {
    ++counters_.busy;
    return SendResult::kBusy;
  }
  if (n >= 0) {
    // A partial frame: the vehicle's decoder drops it and resynchronises on the next.
    ++counters_.busy;
    return SendResult::kBusy;
  }
  lose(std::strerror(errno), now_ns);
  ++counters_.down;
  return SendResult::kDown;
}

bool ReconnectingLink::drain_and_close(int timeout_ms) {
  bool drained = false;
  if (state_ == LinkState::kUp) {
    const Nanos deadline = drain_clock_.now() + Nanos(static_cast<std::int64_t>(timeout_ms) * kNsPerMs);
    // Bounded, unlike a bare tcdrain, which waits for ever on a pty nobody reads.
    while (undelivered_bytes() > 0 && drain_clock_.now() < deadline) {
      drain_clock_.sleep_until(drain_clock_.now() + Nanos(2 * kNsPerMs));
    }
    drained = undelivered_bytes() == 0;
    if (drained) finish_drain();
  }
  close_fd();
  state_ = LinkState::kConnecting;
  detail_ = kClosedDetail;
  return drained;
}

}  // namespace andros::link
