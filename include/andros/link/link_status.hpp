#pragma once
/// The link's state as plain values: what the run loop reports after each
/// send and the operator's view shows. No behaviour, so that whoever holds one
/// cannot reach back into the link.

#include <cstdint>
#include <string>
#include <string_view>

namespace andros::link {

enum class LinkState : std::uint8_t {
  kConnecting,  ///< not open yet, or reopening after a loss
  kUp,          ///< frames are being written
};

enum class SendResult : std::uint8_t {
  kSent,  ///< the whole frame was handed to the driver
  kBusy,  ///< the driver (or a TCP server, as its window shows) still held bytes: this tick skipped, so that no stale
          ///< frame queues
  kDown,  ///< no connection this tick
};

/// LinkStatus::detail of a link the bridge closed itself (drained and closed:
/// a suspend, the run's end), not lost: what tells one from the other in a session.
inline constexpr std::string_view kClosedDetail = "closed";

struct LinkCounters {
  std::uint64_t sent = 0;
  std::uint64_t busy = 0;    ///< ticks skipped because the output queue (or the server) was not empty
  std::uint64_t down = 0;    ///< ticks with no connection
  std::uint64_t losses = 0;  ///< times an open link was lost
};

/// The link carries motion: it is up, and not held to neutral frames (a TCP
/// server that stalled): the one rule for the loop's state, the pad's light and the view.
constexpr bool carries_motion(LinkState state, bool far_end_reading) {
  return state == LinkState::kUp && far_end_reading;
}

/// A link at one moment (Link::status()).
struct LinkStatus {
  LinkState state = LinkState::kConnecting;
  bool far_end_reading = true;  ///< false: the link gets neutral frames only (Link::far_end_reading)
  std::string detail;           ///< why it is not up, empty when up
  LinkCounters counters;

  [[nodiscard]] bool carries_motion() const { return link::carries_motion(state, far_end_reading); }
};

std::string_view to_string(LinkState state);

}  // namespace andros::link
