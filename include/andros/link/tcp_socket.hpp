#pragma once
/// One TCP connection as this side's kernel shows it: all that TcpLink asks
/// of the far end. In `run` it is the kernel's socket (tcp_link.cpp); the
/// fault simulation puts a scripted server on the replay's clock behind it
/// (tests/oracle/tcp_server.hpp), so that the link's own rules (its stall
/// rule, its distrust of a server that stalled, the back-off) run there.

#include <cstddef>
#include <cstdint>

namespace andros::link {

class TcpSocket {
 public:
  virtual ~TcpSocket() = default;

  enum class Connect : std::uint8_t { kOpen, kPending, kFailed };
  /// Starts a new connection without blocking (the last one is closed);
  /// kFailed sets errno.
  virtual Connect connect() = 0;
  /// After kPending: whether the connect has completed; kFailed sets errno.
  virtual Connect connected() = 0;

  /// Bytes written and not sent at all (SIOCOUTQNSD), or -1 with errno set.
  [[nodiscard]] virtual int unsent() const = 0;
  /// Bytes written that the server has not acknowledged, unsent ones
  /// included (SIOCOUTQ), or -1 with errno set.
  [[nodiscard]] virtual int unacknowledged() const = 0;

  /// What the server's acknowledgements report (TCP_INFO).
  struct Window {
    std::uint64_t bytes_acked = 0;
    std::uint32_t window = 0;  ///< its window now (0 where the kernel does not report it: before Linux 5.4)
  };
  /// False with errno set when it cannot be read.
  virtual bool window(Window& out) const = 0;

  /// Reads and drops what the server sent; true when it has closed the
  /// connection (an orderly close).
  virtual bool peer_closed() = 0;
  /// Writes without waiting: the bytes taken, or -1 with errno set.
  virtual long send(const std::uint8_t* data, std::size_t size) = 0;
  /// Makes the coming close a reset: what is still unsent is discarded.
  virtual void abort_on_close() = 0;
  virtual void close() = 0;
};

}  // namespace andros::link
