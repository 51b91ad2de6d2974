#pragma once
/// Frames to a TCP serial server (ser2net, a radio modem's TCP port):
/// `tcp:HOST:PORT`. Connects without blocking the frame clock and reconnects
/// with back-off (250 ms doubling to 4 s) when the server goes away or
/// stalls; bounds what waits unread at the server as far as its window shows
/// (docs/running.md, "Stale commands on a TCP link").

#include <memory>

#include "andros/base/error.hpp"
#include "andros/link/reconnecting_link.hpp"
#include "andros/link/tcp_socket.hpp"

namespace andros::link {

inline constexpr int kTcpMinRetryMs = 250;
inline constexpr int kTcpMaxRetryMs = 4000;
/// A connect that has not completed by then is abandoned and retried.
inline constexpr std::int64_t kTcpConnectTimeoutNs = 3'000'000'000;
/// The most the server may seem to hold unread (its widest window less its
/// window now) before frames are held back: 4 frames beyond the 536 bytes
/// (the default MSS) by which a receiver lets its window fall behind, for
/// small segments, before it moves it, even when its program reads at once.
inline constexpr std::uint32_t kTcpMaxUnreadBytes = 536 + 4 * protocol::kFrameSize;
/// While held back, one frame this often still goes, so that the server's
/// acknowledgement reports its window again.
inline constexpr std::int64_t kTcpProbeNs = 250'000'000;
/// Data waiting and the server's window not moving for this long: the link
/// is stalled, and is dropped and reopened. Not shorter: a server's window
/// moves in steps of up to 536 bytes, over a second apart for a server
/// reading at half the frame rate.
inline constexpr std::int64_t kTcpStallNs = 2'000'000'000;

struct TcpAddress {
  std::string host;
  std::string port;
  SourcePos pos{"--port"};  ///< where it was written, for errors about it
};

/// Splits "tcp:HOST:PORT" ("tcp:[::1]:4001" for IPv6). Throws InputError at
/// pos (the flag, or the config file's line).
TcpAddress parse_tcp_spec(std::string_view spec, const SourcePos& pos = SourcePos{"--port"});

class TcpLink final : public ReconnectingLink {
 public:
  /// Resolves the address now (start-up, before the clock runs): an unknown
  /// host is an InputError.
  explicit TcpLink(const TcpAddress& address);
  /// The same link over another socket (the fault simulation's scripted
  /// server), its drain at shutdown waiting on drain_clock. Its other timing
  /// is the now_ns each send() is given.
  TcpLink(std::string name, std::unique_ptr<TcpSocket> socket, Clock* drain_clock);

  [[nodiscard]] bool far_end_reading() const override { return !suspect_; }

 protected:
  OpenResult open_step(std::int64_t now_ns, std::string& why) override;
  int queued_bytes() const override;
  int undelivered_bytes() const override;
  int backlog(std::int64_t now_ns, std::string& stalled) override;
  long write_bytes(const std::uint8_t* data, std::size_t size) override;
  void close_fd() override;

 private:
  /// What the server's acknowledgements have shown on this connection.
  struct Progress {
    std::uint64_t first_edge = 0;  ///< the edge when the connection came up
    std::uint64_t edge = 0;        ///< right edge of its window: bytes acknowledged + window
    std::uint32_t max_window = 0;  ///< the widest window it has offered
    std::int64_t since_ns = 0;     ///< when the edge last moved, or nothing was waiting
    std::int64_t probe_ns = 0;     ///< when a held-back frame last went anyway
    std::int64_t written = 0;      ///< bytes written on this connection
  };
  OpenResult opened(std::int64_t now_ns);

  std::unique_ptr<TcpSocket> socket_;
  Progress progress_;
  /// The server stalled, and no connection since has shown it reading: what
  /// it acknowledges may never be read, so nothing counts as delivered.
  bool suspect_ = false;
  bool connecting_ = false;
  std::int64_t connect_started_ns_ = 0;
};

}  // namespace andros::link
