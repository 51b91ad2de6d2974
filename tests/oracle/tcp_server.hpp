#pragma once
// The fault simulation's TCP server (docs/testing.md, "Fault simulation": the TCP runs): a
// stand-in for the kernel's socket (link::TcpSocket) under the real TcpLink
// and ReconnectingLink, on the replay's clock, that a script drives, and the
// oracle of what such a server may be sent, written from docs/running.md
// ("tcp:HOST:PORT" and "Stale commands on a TCP link"), not from the link.
//
// The server is an embedded serial server: a fixed 4 kB receive buffer, so
// that its window shows what its program has not read; everything it takes
// is acknowledged at once. The script's link events are its own: `link
// stalled` its program stops reading, `link reading` it reads again (all it
// holds, at every tick), `link down` it resets the connection and refuses
// new ones, `link taken` it closes the connection and refuses new ones,
// `link up` it accepts again.

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <string>
#include <vector>

#include "andros/input/events.hpp"
#include "andros/link/tcp_socket.hpp"
#include "andros/protocol/frame.hpp"
#include "oracle/frame_rules.hpp"
#include "oracle/wire_frame.hpp"

namespace andros::test {

/// What the TCP runs reached, for the simulation's own checks.
struct TcpCoverage {
  std::int64_t frames = 0;          ///< frames the server was sent
  std::int64_t motion = 0;          ///< of them with motion
  std::int64_t stalls_dropped = 0;  ///< connections the link reset as stalled
  std::int64_t distrusted = 0;      ///< frames sent while the server was distrusted (all neutral)
  std::int64_t motion_again = 0;    ///< motion frames sent after a distrusted server read again
  std::int64_t refused = 0;         ///< connection attempts the server refused
  std::int64_t server_ends = 0;     ///< connections the server reset or closed
  std::int64_t backoff_waited = 0;  ///< attempts made after a back-off of 1 s or more
  TcpCoverage& operator+=(const TcpCoverage& o) {
    using C = TcpCoverage;
    for (const auto field : {&C::frames, &C::motion, &C::stalls_dropped, &C::distrusted, &C::motion_again, &C::refused,
                             &C::server_ends, &C::backoff_waited}) {
      this->*field += o.*field;
    }
    return *this;
  }
};

class ScriptedServer final : public link::TcpSocket {
 public:
  /// docs/running.md, "Stale commands on a TCP link": frames held back when
  /// the window is more than 680 bytes (536 + 4 frames) below the widest; a
  /// stall is 2 s of its edge still while frames are held back, and no
  /// connection holds more than 32 frames.
  static constexpr std::size_t kBuffer = 4096;
  static constexpr std::size_t kHeldBack = 536 + 4 * protocol::kFrameSize;
  static constexpr std::int64_t kStallMs = 2000;
  static constexpr std::size_t kMostHeld = 32 * protocol::kFrameSize;
  /// docs/running.md, "tcp:HOST:PORT": retried after 250 ms, doubling up
  /// to 4 s; a connection lost within 5 s of coming up does not reset that.
  static constexpr std::int64_t kFirstRetryMs = 250;
  static constexpr std::int64_t kLastRetryMs = 4000;
  static constexpr std::int64_t kStableMs = 5000;

  /// events: the script's (its link events are this server's); code: the frames' dip-switch code.
  ScriptedServer(const std::vector<input::InputEvent>& events, std::uint8_t code) : code_(code) {
    for (const auto& e : events) {
      if (is_server_event(e.type)) events_.push_back(e);
    }
  }

  static bool is_server_event(input::InputEvent::Type type) {
    using T = input::InputEvent::Type;
    return type == T::kLinkDown || type == T::kLinkUp || type == T::kLinkTaken || type == T::kLinkStalled ||
           type == T::kLinkReading;
  }

  /// The loop's tick at t: the server's events up to t, then its program reads what it holds (when reading).
  void at(std::int64_t t_ms) {
    using T = input::InputEvent::Type;
    t_ = t_ms;
    for (; next_ < events_.size() && events_[next_].t_ms <= t_; ++next_) {
      switch (events_[next_].type) {
        case T::kLinkStalled: reading_ = false; break;
        case T::kLinkReading: reading_ = true; break;
        case T::kLinkUp: accepting_ = true; break;
        case T::kLinkDown:
        case T::kLinkTaken:
          accepting_ = false;
          if (c_.open && c_.ended == End::kNone) {
            c_.ended = events_[next_].type == T::kLinkDown ? End::kReset : End::kClosed;
            ++coverage_.server_ends;
          }
          break;
        default: break;
      }
    }
    if (reading_ && c_.open && c_.ended == End::kNone && c_.unread > 0) read_all();
  }

  [[nodiscard]] const std::string& violation() const { return violation_; }
  [[nodiscard]] const TcpCoverage& coverage() const { return coverage_; }

  // The socket, as TcpLink sees it.
  Connect connect() override {
    // [rule: tcp-backoff]
    if (t_ < earliest_ms_) {
      fail("a connection attempt " + std::to_string(earliest_ms_ - t_) + " ms before the back-off (" +
           std::to_string(backoff_ms_) + " ms) allowed it");
    }
    if (backoff_ms_ >= 1000 && t_ >= earliest_ms_) ++coverage_.backoff_waited;
    if (c_.open) close();
    if (!accepting_) {
      ++coverage_.refused;
      failed(false);
      errno = ECONNREFUSED;
      return Connect::kFailed;
    }
    c_ = Connection{.open = true, .opened_ms = t_};
    return Connect::kOpen;
  }
  Connect connected() override { return Connect::kOpen; }
  [[nodiscard]] int unsent() const override { return static_cast<int>(c_.unsent); }
  [[nodiscard]] int unacknowledged() const override { return static_cast<int>(c_.unsent); }
  bool window(Window& out) const override {
    out = Window{.bytes_acked = c_.arrived, .window = static_cast<std::uint32_t>(kBuffer - c_.unread)};
    return true;
  }
  bool peer_closed() override {
    if (c_.ended != End::kClosed) return false;
    lost();
    return true;
  }
  long send(const std::uint8_t* data, std::size_t size) override {
    if (c_.ended == End::kReset) {
      lost();
      errno = ECONNRESET;
      return -1;
    }
    const std::size_t room = kBuffer - c_.unsent;
    if (room == 0) {
      errno = EAGAIN;
      return -1;
    }
    const std::size_t taken = std::min(size, room);
    if (taken == protocol::kFrameSize) check_frame(data);
    c_.unsent += taken;
    arrive();
    return static_cast<long>(taken);
  }
  void abort_on_close() override { c_.abort = true; }
  void close() override {
    if (!c_.open) return;
    if (c_.abort) {
      // [rule: tcp-stall] Dropped as stalled only after 2 s of its edge still with frames held back.
      if (c_.over_since_ms < 0 || t_ < c_.over_since_ms + kStallMs) {
        fail(
            "the link reset the connection as stalled, but the server had read, or had no frames waiting, "
            "within the last 2 s");
      }
      ++coverage_.stalls_dropped;
      distrusted_ = true;
      lost();
    }
    c_.open = false;
  }

 private:
  enum class End : std::uint8_t { kNone, kReset, kClosed };
  /// One connection, as the server's kernel and program see it.
  struct Connection {
    bool open = false;       ///< not closed by the link
    End ended = End::kNone;  ///< reset or closed by the server
    bool abort = false;      ///< the link's close will be a reset
    bool lost = false;       ///< the link has met its end (or reset it), once
    std::int64_t opened_ms = 0;
    std::size_t unread = 0;           ///< held by the server's kernel, not read by its program
    std::size_t unsent = 0;           ///< written by the link, beyond the server's window
    std::uint64_t arrived = 0;        ///< taken (and acknowledged) by the server's kernel
    bool read = false;                ///< its program has read on this connection
    std::int64_t over_since_ms = -1;  ///< when frames came to wait (held back, or distrusted), with no read since
  };

  void fail(const std::string& why) {
    if (violation_.empty()) violation_ = "TCP server at t=" + std::to_string(t_) + ": " + why;
  }

  // The bytes beyond the window go as it opens.
  void arrive() {
    const std::size_t moved = std::min(c_.unsent, kBuffer - c_.unread);
    c_.unsent -= moved;
    c_.unread += moved;
    c_.arrived += moved;
    // Waiting: frames held back, or any frame at all to a server that stalled and has not read since (what it
    // acknowledges may never be read: TcpLink's suspicion).
    if ((c_.unread > kHeldBack || (distrusted_ && c_.arrived > 0)) && c_.over_since_ms < 0) c_.over_since_ms = t_;
    // [rule: tcp-stall]
    if (c_.unread > kMostHeld)
      fail(std::to_string(c_.unread / protocol::kFrameSize) + " frames held unread (at most 32)");
  }

  void read_all() {
    c_.unread = 0;
    c_.read = true;
    c_.over_since_ms = -1;
    read_after_distrust_ = read_after_distrust_ || distrusted_;
    distrusted_ = false;
    arrive();
  }

  // A frame the link wrote whole, read as the vehicle would.
  void check_frame(const std::uint8_t* bytes) {
    protocol::Frame frame{};
    std::copy(bytes, bytes + frame.size(), frame.begin());
    protocol::DataBytes data{};
    // [rule: tcp-wire] The bytes the server got decode, with the code, valid.
    auto broken = read_wire_frame(frame, data);
    const auto s = protocol::read_signals(data);
    if (broken.empty()) broken = frame_errors(data, s, code_);
    if (!broken.empty()) return fail("a frame on the wire: " + broken);
    ++coverage_.frames;
    // [rule: tcp-stall] Its edge still for 2 s with frames held back: no more frames on that connection.
    if (c_.over_since_ms >= 0 && t_ >= c_.over_since_ms + kStallMs) {
      fail("a frame to a server that has read nothing for " + std::to_string(t_ - c_.over_since_ms) +
           " ms with frames held back (a stall after 2 s)");
    }
    if (distrusted_) ++coverage_.distrusted;
    const auto moving = motion(s);
    if (!moving) return;
    ++coverage_.motion;
    // [rule: tcp-distrust]
    if (distrusted_) fail(*moving + " to a server that stalled and has not been seen reading since");
    if (read_after_distrust_) ++coverage_.motion_again;
  }

  // The link met the connection's end (or reset it): the back-off from now.
  void lost() {
    if (c_.lost) return;
    c_.lost = true;
    failed(t_ - c_.opened_ms >= kStableMs);
  }
  void failed(bool after_stable) {
    if (after_stable) backoff_ms_ = kFirstRetryMs;
    earliest_ms_ = t_ + backoff_ms_;
    backoff_ms_ = std::min(backoff_ms_ * 2, kLastRetryMs);
  }

  std::uint8_t code_;
  std::vector<input::InputEvent> events_;
  std::size_t next_ = 0;
  std::int64_t t_ = 0;
  bool reading_ = true;
  bool accepting_ = true;
  Connection c_;
  bool distrusted_ = false;                  ///< reset as stalled by the link, not read on a connection since
  bool read_after_distrust_ = false;         ///< a distrusted server has read since
  std::int64_t backoff_ms_ = kFirstRetryMs;  ///< what the next failure waits
  std::int64_t earliest_ms_ = 0;
  std::string violation_;
  TcpCoverage coverage_;
};

}  // namespace andros::test
