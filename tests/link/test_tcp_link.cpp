#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>

#include <algorithm>

#include "andros/base/clock.hpp"
#include "andros/base/error.hpp"
#include "andros/link/pty_pair.hpp"
#include "andros/link/tcp_link.hpp"
#include "support/frame_reader.hpp"

namespace andros::link {
namespace {

/// A TCP listener on 127.0.0.1, on a port the kernel picks. With rcvbuf set,
/// its connections have that fixed receive buffer (an embedded serial
/// server's), so their window shows what waits unread.
struct Listener {
  explicit Listener(int rcvbuf = 0) : fd(socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0)) {
    if (rcvbuf > 0) setsockopt(fd.get(), SOL_SOCKET, SO_RCVBUF, &rcvbuf, sizeof rcvbuf);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    bind(fd.get(), reinterpret_cast<sockaddr*>(&a), sizeof a);
    listen(fd.get(), 4);
    socklen_t len = sizeof a;
    getsockname(fd.get(), reinterpret_cast<sockaddr*>(&a), &len);
    port = ntohs(a.sin_port);
  }
  /// Accepts one connection, sending frames on link meanwhile (at most 2 s).
  UniqueFd accept_while_sending(Link& link, const protocol::Frame& frame) const {
    for (int i = 0; i < 200; ++i) {
      link.send(frame, monotonic_ns());
      pollfd p{fd.get(), POLLIN, 0};
      if (poll(&p, 1, 10) == 1) return UniqueFd(accept(fd.get(), nullptr, nullptr));
    }
    return UniqueFd();
  }
  UniqueFd fd;
  int port = 0;
};

protocol::Frame frame_with_drive(std::uint8_t drive) {
  protocol::ControlState s;
  s[protocol::signal_id("drive")] = drive;
  return protocol::encode(protocol::FrameBuilder(0x01).build(s));
}

TEST(TcpLink, ParsesTheSpec) {
  auto a = parse_tcp_spec("tcp:radio.local:4001");
  EXPECT_EQ(a.host, "radio.local");
  EXPECT_EQ(a.port, "4001");
  a = parse_tcp_spec("tcp:[::1]:2000");
  EXPECT_EQ(a.host, "::1");
  EXPECT_EQ(a.port, "2000");
  EXPECT_THROW(parse_tcp_spec("tcp:host"), InputError);
  EXPECT_THROW(parse_tcp_spec("tcp:host:0"), InputError);
  EXPECT_THROW(parse_tcp_spec("tcp::4001"), InputError);
  EXPECT_THROW(parse_tcp_spec("tcp:host:70000"), InputError);
  EXPECT_THROW(parse_tcp_spec("tcp:127.0.0.1:99999999999999999999"), InputError);
}

TEST(TcpLink, PortErrorsNameWhereThePortWasWritten) {
  try {
    parse_tcp_spec("tcp:host:0", SourcePos{"bridge.conf", 3, 12});
    FAIL() << "port 0 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.pos().file, "bridge.conf");
    EXPECT_EQ(e.pos().line, 3);
    EXPECT_EQ(e.pos().column, 12);
  }
  try {
    TcpLink(parse_tcp_spec("tcp:no-such-host.invalid:4001", SourcePos{"bridge.conf", 4, 12}));
    FAIL() << "unresolvable host accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.pos().file, "bridge.conf");
    EXPECT_EQ(e.pos().line, 4);
  }
}

/// Whole frames waiting unread on a server's connection.
std::size_t frames_waiting(int fd) {
  int bytes = 0;
  ioctl(fd, FIONREAD, &bytes);
  return static_cast<std::size_t>(bytes) / protocol::kFrameSize;
}

TEST(TcpLink, AServerThatStopsReadingIsDroppedWithFewFramesWaiting) {
  Listener server(4096);
  TcpLink link(TcpAddress{"127.0.0.1", std::to_string(server.port)});
  auto conn = server.accept_while_sending(link, frame_with_drive(200));
  ASSERT_TRUE(conn);
  EXPECT_TRUE(link.far_end_reading());
  // 25 Hz, never read: at most 5 s for the link to give up on the server.
  int ticks = 0;
  for (; ticks < 125 && link.counters().losses == 0; ++ticks) {
    link.send(frame_with_drive(200), monotonic_ns());
    poll(nullptr, 0, 40);
  }
  EXPECT_EQ(link.counters().losses, 1u);
  EXPECT_EQ(link.state(), LinkState::kConnecting);
  EXPECT_LE(ticks, 100);  // 19 frames, then 2 s without progress (50 ticks), with room for a loaded machine
  EXPECT_GT(link.counters().busy, 0u);
  EXPECT_LE(frames_waiting(conn.get()), 32u);  // docs/running.md
  // Until it is seen reading, it is sent nothing that moves (the run loop asks).
  EXPECT_FALSE(link.far_end_reading());
  // The link comes back on its own, but the server that stalled has not been
  // seen reading since: what it acknowledges does not count as delivered.
  auto again = server.accept_while_sending(link, frame_with_drive(128));
  EXPECT_TRUE(again);
  EXPECT_FALSE(link.drain_and_close(100));
}

TEST(TcpLink, ASlowReaderIsNotAStallAndNeverFallsFarBehind) {
  Listener server(4096);
  TcpLink link(TcpAddress{"127.0.0.1", std::to_string(server.port)});
  auto conn = server.accept_while_sending(link, frame_with_drive(200));
  ASSERT_TRUE(conn);
  // 4 s at 25 Hz to a server that reads one frame each 80 ms (by the clock,
  // however slowly this loop runs on a loaded machine).
  std::size_t most_waiting = 0;
  std::uint8_t scratch[protocol::kFrameSize];
  const std::int64_t start = monotonic_ns();
  std::int64_t read = 0;
  for (int tick = 0; tick < 100; ++tick) {
    link.send(frame_with_drive(200), monotonic_ns());
    most_waiting = std::max(most_waiting, frames_waiting(conn.get()));
    for (; read < (monotonic_ns() - start) / 80'000'000; ++read) {
      recv(conn.get(), scratch, sizeof scratch, MSG_DONTWAIT);
    }
    poll(nullptr, 0, 40);
  }
  EXPECT_EQ(link.counters().losses, 0u);
  EXPECT_GT(link.counters().busy, 0u);
  EXPECT_LE(most_waiting, 32u);
}

TEST(TcpLink, AServerThatAcceptsAndClosesIsRetriedWithBackOff) {
  Listener server;
  TcpLink link(TcpAddress{"127.0.0.1", std::to_string(server.port)});
  // 3 s: attempts at 0, 0.25, 0.75 and 1.75 s (250 ms doubling), not every few ticks.
  int accepts = 0;
  const std::int64_t end = monotonic_ns() + 3'000'000'000;
  while (monotonic_ns() < end) {
    link.send(frame_with_drive(128), monotonic_ns());
    pollfd p{server.fd.get(), POLLIN, 0};
    if (poll(&p, 1, 10) == 1) {
      UniqueFd(accept(server.fd.get(), nullptr, nullptr)).reset();
      ++accepts;
    }
  }
  EXPECT_GE(accepts, 2);
  EXPECT_LE(accepts, 5);
}

TEST(TcpLink, StreamsToALocalListenerAndReconnects) {
  Listener server;
  TcpLink link(TcpAddress{"127.0.0.1", std::to_string(server.port)});
  auto conn = server.accept_while_sending(link, frame_with_drive(50));
  ASSERT_TRUE(conn);
  // Frames sent before accept() returned may already be queued: read until ours show.
  test::FrameReader reader(conn.get());
  for (int i = 0; i < 200 && link.state() != LinkState::kUp; ++i) link.send(frame_with_drive(50), monotonic_ns());
  ASSERT_EQ(link.state(), LinkState::kUp);
  ASSERT_EQ(link.send(frame_with_drive(60), monotonic_ns()), SendResult::kSent);
  bool seen = false;
  for (int i = 0; i < 20 && !seen; ++i) {
    for (const auto& f : reader.next(1, 100)) seen = seen || (f.valid && f.data[7] == 60);
  }
  EXPECT_TRUE(seen);

  // The server goes away: the link notices and, once it is back, reconnects.
  conn.reset();
  SendResult r = SendResult::kSent;
  for (int i = 0; i < 200 && r == SendResult::kSent; ++i) {
    r = link.send(frame_with_drive(61), monotonic_ns());
    poll(nullptr, 0, 5);
  }
  EXPECT_NE(r, SendResult::kSent);
  EXPECT_EQ(link.counters().losses, 1u);
  auto again = server.accept_while_sending(link, frame_with_drive(62));
  EXPECT_TRUE(again);
  EXPECT_TRUE(link.drain_and_close(300));  // acknowledged, by a server never seen stalling
}

TEST(TcpLink, UnresolvableHostIsBadInput) {
  EXPECT_THROW(TcpLink(TcpAddress{"no-such-host.invalid", "4001"}), InputError);
}

}  // namespace
}  // namespace andros::link
