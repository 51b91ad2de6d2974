#include "andros/link/tcp_link.hpp"

#include <fcntl.h>
#include <linux/sockios.h>
#include <linux/tcp.h>  // tcp_info with tcpi_snd_wnd (glibc's netinet/tcp.h lacks it)
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <memory>

#include "andros/base/clock.hpp"
#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "andros/base/unique_fd.hpp"

namespace andros::link {

TcpAddress parse_tcp_spec(std::string_view spec, const SourcePos& pos) {
  if (!spec.starts_with("tcp:")) throw InputError(pos, "expected tcp:HOST:PORT");
  auto rest = spec.substr(4);
  TcpAddress out;
  if (rest.starts_with("[")) {
    const auto close = rest.find(']');
    if (close == std::string_view::npos || close + 1 >= rest.size() || rest[close + 1] != ':') {
      throw InputError(pos, "'" + std::string(spec) + "' is not tcp:[ADDRESS]:PORT");
    }
    out.host = std::string(rest.substr(1, close - 1));
    out.port = std::string(rest.substr(close + 2));
  } else {
    const auto colon = rest.rfind(':');
    if (colon == std::string_view::npos) {
      throw InputError(pos, "'" + std::string(spec) + "' is not tcp:HOST:PORT");
    }
    out.host = std::string(rest.substr(0, colon));
    out.port = std::string(rest.substr(colon + 1));
  }
  // Digits only (no sign), at most 5 of them.
  const bool digits =
      !out.port.empty() && out.port.size() <= 5 && out.port.find_first_not_of("0123456789") == std::string::npos;
  const auto port = to_integer(out.port);
  if (out.host.empty() || !digits || !port || *port < 1 || *port > 65535) {
    throw InputError(pos, "'" + std::string(spec) + "' is not tcp:HOST:PORT (PORT 1..65535)");
  }
  out.pos = pos;
  return out;
}

namespace {

/// The kernel's socket to the address, non-blocking.
class KernelSocket final : public TcpSocket {
 public:
  KernelSocket(const sockaddr_storage& addr, socklen_t addr_len) : addr_(addr), addr_len_(addr_len) {}

  Connect connect() override {
    fd_.reset(::socket(addr_.ss_family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
    if (!fd_) return Connect::kFailed;
    const int one = 1;
    // A frame is one small write: send it now, not after Nagle's delay.
    setsockopt(fd_.get(), IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    // What this side may hold: one frame unsent, a few kB in all.
    const int lowat = static_cast<int>(protocol::kFrameSize);
    setsockopt(fd_.get(), IPPROTO_TCP, TCP_NOTSENT_LOWAT, &lowat, sizeof lowat);
    const int sndbuf = 4096;
    setsockopt(fd_.get(), SOL_SOCKET, SO_SNDBUF, &sndbuf, sizeof sndbuf);
    if (::connect(fd_.get(), reinterpret_cast<const sockaddr*>(&addr_), addr_len_) == 0) return Connect::kOpen;
    return errno == EINPROGRESS ? Connect::kPending : Connect::kFailed;
  }

  Connect connected() override {
    pollfd p{fd_.get(), POLLOUT, 0};
    if (poll(&p, 1, 0) == 0) return Connect::kPending;
    int err = 0;
    socklen_t len = sizeof err;
    getsockopt(fd_.get(), SOL_SOCKET, SO_ERROR, &err, &len);
    errno = err;
    return err == 0 ? Connect::kOpen : Connect::kFailed;
  }

  [[nodiscard]] int unsent() const override {
    int queued = 0;
    if (ioctl(fd_.get(), SIOCOUTQNSD, &queued) != 0) return -1;
    return queued;
  }

  [[nodiscard]] int unacknowledged() const override {
    int outq = 0;
    if (ioctl(fd_.get(), SIOCOUTQ, &outq) != 0) return -1;
    return outq;
  }

  bool window(Window& out) const override {
    tcp_info info{};
    socklen_t len = sizeof info;
    if (getsockopt(fd_.get(), IPPROTO_TCP, TCP_INFO, &info, &len) != 0) return false;
    const bool has_window = len >= offsetof(tcp_info, tcpi_snd_wnd) + sizeof info.tcpi_snd_wnd;
    out = Window{.bytes_acked = info.tcpi_bytes_acked, .window = has_window ? info.tcpi_snd_wnd : 0};
    return true;
  }

  bool peer_closed() override {
    std::uint8_t scratch[256];
    return ::recv(fd_.get(), scratch, sizeof scratch, MSG_DONTWAIT) == 0;
  }

  long send(const std::uint8_t* data, std::size_t size) override {
    return ::send(fd_.get(), data, size, MSG_NOSIGNAL | MSG_DONTWAIT);
  }

  void abort_on_close() override {
    const linger abort{1, 0};
    setsockopt(fd_.get(), SOL_SOCKET, SO_LINGER, &abort, sizeof abort);
  }

  void close() override { fd_.reset(); }

 private:
  sockaddr_storage addr_;
  socklen_t addr_len_;
  UniqueFd fd_;
};

/// The address resolved (start-up, before the clock runs): an unknown host is an InputError.
std::unique_ptr<TcpSocket> resolve(const TcpAddress& address) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const int rc = getaddrinfo(address.host.c_str(), address.port.c_str(), &hints, &found);
  if (rc != 0 || found == nullptr) {
    throw InputError(address.pos, "cannot resolve '" + address.host + "': " + gai_strerror(rc));
  }
  sockaddr_storage addr{};
  std::memcpy(&addr, found->ai_addr, found->ai_addrlen);
  const socklen_t len = found->ai_addrlen;
  freeaddrinfo(found);
  return std::make_unique<KernelSocket>(addr, len);
}

}  // namespace

TcpLink::TcpLink(const TcpAddress& address)
    : TcpLink("tcp " + address.host + ":" + address.port, resolve(address), nullptr) {}

TcpLink::TcpLink(std::string name, std::unique_ptr<TcpSocket> socket, Clock* drain_clock)
    : ReconnectingLink(std::move(name), kTcpMinRetryMs, kTcpMaxRetryMs, drain_clock), socket_(std::move(socket)) {}

ReconnectingLink::OpenResult TcpLink::open_step(std::int64_t now_ns, std::string& why) {
  if (!connecting_) {
    const auto started = socket_->connect();
    if (started == TcpSocket::Connect::kOpen) return opened(now_ns);
    if (started == TcpSocket::Connect::kFailed) {
      why = std::strerror(errno);
      return OpenResult::kFailed;
    }
    connecting_ = true;
    connect_started_ns_ = now_ns;
  }
  const auto done = socket_->connected();
  if (done == TcpSocket::Connect::kPending) {
    if (now_ns - connect_started_ns_ < kTcpConnectTimeoutNs) return OpenResult::kPending;
    connecting_ = false;
    why = "connect timed out";
    return OpenResult::kFailed;
  }
  connecting_ = false;
  if (done == TcpSocket::Connect::kFailed) {
    why = std::strerror(errno);
    return OpenResult::kFailed;
  }
  return opened(now_ns);
}

ReconnectingLink::OpenResult TcpLink::opened(std::int64_t now_ns) {
  progress_ = Progress{.since_ns = now_ns};
  return OpenResult::kOpen;
}

int TcpLink::queued_bytes() const {
  // Bytes not yet sent at all (not those sent and waiting for an ACK): only
  // these would carry a stale command.
  return socket_->unsent();
}

int TcpLink::undelivered_bytes() const {
  const int outq = socket_->unacknowledged();  // unsent, and sent but not acknowledged
  if (outq < 0) return -1;
  return suspect_ ? static_cast<int>(std::max<std::int64_t>(outq, progress_.written)) : outq;
}

int TcpLink::backlog(std::int64_t now_ns, std::string& stalled) {
  const int unsent = queued_bytes();
  const int outq = undelivered_bytes();
  TcpSocket::Window info;
  if (unsent < 0 || outq < 0 || !socket_->window(info)) return -1;
  // The server's window shrinks as its kernel holds bytes its program has not
  // read (kernels before 5.4 do not report it: then only acknowledgements count).
  const std::uint32_t window = info.window;
  progress_.max_window = std::max(progress_.max_window, window);
  const std::uint32_t unread = progress_.max_window - window;
  const std::uint64_t edge = info.bytes_acked + window;
  if (progress_.first_edge == 0) progress_.first_edge = edge;
  if (edge > progress_.first_edge) suspect_ = false;  // its program has read
  const bool waiting = outq > 0 || unread > kTcpMaxUnreadBytes;
  if (!waiting || edge > progress_.edge) progress_.since_ns = now_ns;
  progress_.edge = std::max(progress_.edge, edge);
  if (now_ns - progress_.since_ns >= kTcpStallNs) {
    // Dropped with a reset, so that the frame still unsent here is never delivered late.
    socket_->abort_on_close();
    suspect_ = true;
    stalled = "stalled: the server took nothing for " + std::to_string(kTcpStallNs / kNsPerMs) + " ms";
    return 0;
  }
  if (unsent > 0) return unsent;
  if (unread > kTcpMaxUnreadBytes && now_ns - progress_.probe_ns < kTcpProbeNs) return static_cast<int>(unread);
  if (unread > kTcpMaxUnreadBytes) progress_.probe_ns = now_ns;
  return 0;
}

long TcpLink::write_bytes(const std::uint8_t* data, std::size_t size) {
  // The vehicle never talks back; anything a serial server sends is read and
  // dropped, and an orderly close by the server shows here as a loss.
  if (socket_->peer_closed()) {
    errno = ECONNRESET;
    return -1;
  }
  const long sent = socket_->send(data, size);
  if (sent > 0) progress_.written += sent;
  return sent;
}

void TcpLink::close_fd() {
  socket_->close();
  connecting_ = false;
}

}  // namespace andros::link
