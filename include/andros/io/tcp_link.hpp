#pragma once
/// Frames to a TCP serial server (ser2net, a radio modem's TCP port):
/// `tcp:HOST:PORT`. Connects without blocking the frame clock and reconnects
/// with back-off (250 ms doubling to 4 s) when the server goes away.

#include <netdb.h>
#include <sys/socket.h>

#include "andros/error.hpp"
#include "andros/io/reconnecting_link.hpp"

namespace andros::io {

inline constexpr int kTcpMinRetryMs = 250;
inline constexpr int kTcpMaxRetryMs = 4000;
/// A connect that has not completed by then is abandoned and retried.
inline constexpr std::int64_t kTcpConnectTimeoutNs = 3'000'000'000;

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

 protected:
  OpenResult open_step(std::string& why) override;
  int queued_bytes() const override;
  long write_bytes(const std::uint8_t* data, std::size_t size) override;

 private:
  sockaddr_storage addr_{};
  socklen_t addr_len_ = 0;
  bool connecting_ = false;
  std::int64_t connect_started_ns_ = 0;
};

}  // namespace andros::io
