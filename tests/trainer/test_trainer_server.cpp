// The trainer's server against issue 37's security requirements, through a
// raw socket client: what a browser, a hostile page or a stalled reader would send.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <string>

#include "andros/trainer/stream_hub.hpp"
#include "andros/trainer/trainer_server.hpp"

namespace andros::trainer {
namespace {

constexpr std::string_view kPage = "<!DOCTYPE html><html><body>the page</body></html>";

/// A client socket connected to 127.0.0.1:port (closed with it).
class RawClient {
 public:
  explicit RawClient(int port, int receive_buffer = 0) : fd_(socket(AF_INET, SOCK_STREAM, 0)) {
    if (receive_buffer > 0) setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &receive_buffer, sizeof receive_buffer);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected_ = connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  }
  ~RawClient() { close(fd_); }
  RawClient(const RawClient&) = delete;
  RawClient& operator=(const RawClient&) = delete;

  [[nodiscard]] bool connected() const { return connected_; }
  void send_text(const std::string& text) const {
    ASSERT_EQ(write(fd_, text.data(), text.size()), ssize_t(text.size()));
  }
  /// Reads until `what` comes after the last thing waited for (10 s at
  /// most); false when the peer closed or time ran out first.
  bool wait_for(std::string_view what) {
    char buf[4096];
    for (int waited = 0; waited < 100;) {
      if (const auto at = got_.find(what, pos_); at != std::string::npos) {
        pos_ = at + what.size();
        return true;
      }
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, 100) == 0) {
        ++waited;
        continue;
      }
      const auto n = read(fd_, buf, sizeof buf);
      if (n <= 0) return false;
      got_.append(buf, static_cast<std::size_t>(n));
    }
    return false;
  }
  /// Everything until the peer closes.
  const std::string& all() {
    wait_for("\x01never sent");
    return got_;
  }

 private:
  int fd_;
  bool connected_ = false;
  std::string got_;
  std::size_t pos_ = 0;
};

std::string get(const std::string& path, const std::string& host) {
  return "GET " + path + " HTTP/1.1\r\nHost: " + host + "\r\nConnection: close\r\n\r\n";
}

class TrainerServerTest : public ::testing::Test {
 protected:
  void start(HubLimits limits = {}, ServerOptions options = {}) {
    hub_ = std::make_unique<StreamHub>(limits);
    options.listen.port = 0;  // any free port
    server_ = std::make_unique<TrainerServer>(options, *hub_, kPage);
    std::string why;
    ASSERT_TRUE(server_->start(&why)) << why;
  }
  [[nodiscard]] int port() const { return server_->address().port; }
  [[nodiscard]] std::string host() const { return server_->address().host_header(); }
  std::string answer(const std::string& request) {
    RawClient c(port());
    EXPECT_TRUE(c.connected());
    c.send_text(request);
    return c.all();
  }

  std::unique_ptr<StreamHub> hub_;
  std::unique_ptr<TrainerServer> server_;
};

TEST_F(TrainerServerTest, ServesThePageTheStateAndTheStreamToItsOwnHost) {
  start();
  EXPECT_EQ(answer(get("/", host())).rfind("HTTP/1.1 200", 0), 0U);
  EXPECT_NE(answer(get("/", host())).find("the page"), std::string::npos);
  hub_->publish(R"({"tick":7})");
  EXPECT_NE(answer(get("/state", host())).find(R"({"tick":7})"), std::string::npos);
  RawClient stream(port());
  stream.send_text(get("/events", host()));
  EXPECT_TRUE(stream.wait_for("text/event-stream"));
  EXPECT_TRUE(stream.wait_for(R"(data: {"tick":7})")) << "the latest object first";
  hub_->publish(R"({"tick":8})");
  EXPECT_TRUE(stream.wait_for(R"(data: {"tick":8})"));
}

TEST_F(TrainerServerTest, ARequestForAnotherHostIsRefused) {
  start();
  for (const std::string& wrong : {"evil.example:" + std::to_string(port()), std::string("localhost:1"),
                                   "127.0.0.1:" + std::to_string(port() + 1), std::string("")}) {
    const auto got = answer(get("/state", wrong));
    EXPECT_EQ(got.rfind("HTTP/1.1 403", 0), 0U) << wrong << ": " << got;
  }
  const auto none = answer("GET / HTTP/1.1\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(none.rfind("HTTP/1.1 403", 0), 0U) << none;
}

TEST_F(TrainerServerTest, APathWithDotDotReachesNothing) {
  start();
  for (const char* path :
       {"/../etc/passwd", "/..%2f..%2fetc%2fpasswd", "/%2e%2e/state", "/state/..", "/./", "/index.html"}) {
    const auto got = answer(get(path, host()));
    EXPECT_EQ(got.rfind("HTTP/1.1 404", 0), 0U) << path << ": " << got;
    EXPECT_EQ(got.find("root:"), std::string::npos);
  }
}

TEST_F(TrainerServerTest, EveryMethodButGetIsRefused) {
  start();
  for (const char* method : {"POST", "PUT", "DELETE", "PATCH", "OPTIONS"}) {
    const auto got = answer(std::string(method) + " /state HTTP/1.1\r\nHost: " + host() +
                            "\r\nContent-Length: 2\r\nConnection: close\r\n\r\n{}");
    EXPECT_EQ(got.rfind("HTTP/1.1 405", 0), 0U) << method << ": " << got;
  }
}

TEST_F(TrainerServerTest, OneStreamMoreThanTheLimitIsRefusedAndAPlaceFreedIsTakenAgain) {
  start(HubLimits{.max_clients = 2});
  std::vector<std::unique_ptr<RawClient>> streams;
  for (int i = 0; i < 2; ++i) {
    streams.push_back(std::make_unique<RawClient>(port()));
    streams.back()->send_text(get("/events", host()));
    EXPECT_TRUE(streams.back()->wait_for("HTTP/1.1 200"));
  }
  EXPECT_EQ(answer(get("/events", host())).rfind("HTTP/1.1 503", 0), 0U);
  // The page and the state are still served.
  EXPECT_EQ(answer(get("/state", host())).rfind("HTTP/1.1 200", 0), 0U);
  streams.pop_back();  // one leaves: its place is free once the server sees it gone
  bool joined = false;
  for (int i = 0; i < 50 && !joined; ++i) {
    hub_->publish("{}");  // the server finds a closed client when it next writes to it
    RawClient c(port());
    c.send_text(get("/events", host()));
    joined = c.wait_for("HTTP/1.1 200");
    if (!joined) usleep(100'000);
  }
  EXPECT_TRUE(joined);
}

TEST_F(TrainerServerTest, AStalledClientIsDroppedAndTheOthersGoOn) {
  ServerOptions options;
  options.write_timeout = std::chrono::milliseconds(300);
  start(HubLimits{.max_clients = 4, .queue_frames = 8}, options);
  RawClient stalled(port(), 1024);  // never reads: its socket fills, then its queue
  stalled.send_text(get("/events", host()));
  RawClient reader(port());
  reader.send_text(get("/events", host()));
  ASSERT_TRUE(reader.wait_for("HTTP/1.1 200"));
  const std::string big(16 * 1024, 'x');
  // Publishing never waits: were it to wait on the stalled client, this loop would never end.
  for (int i = 0; i < 400 && hub_->counters().dropped == 0; ++i) {
    hub_->publish("{\"n\":" + std::to_string(i) + ",\"pad\":\"" + big + "\"}");
    ASSERT_TRUE(reader.wait_for("\"}\n\n"));
    usleep(5'000);
  }
  EXPECT_EQ(hub_->counters().dropped, 1U);
  hub_->publish(R"({"n":"last"})");
  EXPECT_TRUE(reader.wait_for(R"({"n":"last"})"));
}

TEST_F(TrainerServerTest, APortTakenIsSaidNotThrown) {
  start();
  StreamHub other_hub;
  ServerOptions options;
  options.listen.port = port();
  TrainerServer second(options, other_hub, kPage);
  std::string why;
  EXPECT_FALSE(second.start(&why));
  EXPECT_NE(why.find("cannot listen on 127.0.0.1:" + std::to_string(port())), std::string::npos) << why;
}

TEST(StreamHub, AClientAQueueBehindIsDroppedWithoutWaiting) {
  StreamHub hub(HubLimits{.max_clients = 2, .queue_frames = 3});
  auto slow = hub.subscribe();
  auto quick = hub.subscribe();
  ASSERT_TRUE(slow && quick);
  EXPECT_EQ(hub.subscribe(), nullptr);
  for (int i = 0; i < 3; ++i) {
    hub.publish(std::to_string(i));
    const auto got = quick->next(std::chrono::milliseconds(0));
    ASSERT_TRUE(got.has_value());
  }
  hub.publish("3");  // the slow one's queue is full: dropped
  EXPECT_FALSE(slow->next(std::chrono::milliseconds(0)).has_value());
  const auto got = quick->next(std::chrono::milliseconds(0));
  ASSERT_TRUE(got.has_value());
  ASSERT_EQ(got->size(), 1U);
  EXPECT_EQ(*got->front(), "3");
  EXPECT_EQ(hub.counters().dropped, 1U);
  auto third = hub.subscribe();  // the dropped one's place is free
  EXPECT_NE(third, nullptr);
}

TEST(ListenAddress, ParsesAddrPortAndRefusesTheRest) {
  const auto a = parse_listen("0.0.0.0:9000", {"--listen"});
  EXPECT_EQ(a.host, "0.0.0.0");
  EXPECT_EQ(a.port, 9000);
  EXPECT_FALSE(a.loopback());
  for (const auto* bad : {"9000", ":9000", "host:", "host:0", "host:65536", "host:12x", "a/b:80", "a b:80"}) {
    EXPECT_THROW(parse_listen(bad, {"--listen"}), InputError) << bad;
  }
}

}  // namespace
}  // namespace andros::trainer
