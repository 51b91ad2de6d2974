#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstddef>
#include <cstdlib>
#include <string>

#include "andros/base/service_notify.hpp"
#include "andros/base/unique_fd.hpp"

namespace andros {
namespace {

/// An abstract unix datagram socket standing in for the service manager's.
struct Manager {
  UniqueFd fd{::socket(AF_UNIX, SOCK_DGRAM | SOCK_NONBLOCK, 0)};
  std::string name = "andros-notify-test-" + std::to_string(::getpid());

  Manager() {
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    name.copy(addr.sun_path + 1, name.size());
    const auto length = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + 1 + name.size());
    EXPECT_EQ(::bind(fd.get(), reinterpret_cast<const sockaddr*>(&addr), length), 0);
    ::setenv("NOTIFY_SOCKET", ("@" + name).c_str(), 1);
  }
  ~Manager() {
    ::unsetenv("NOTIFY_SOCKET");
    ::unsetenv("WATCHDOG_USEC");
    ::unsetenv("WATCHDOG_PID");
  }
  /// The next message, "" when none is waiting.
  std::string next() const {
    char buf[256];
    const auto n = ::recv(fd.get(), buf, sizeof buf, 0);
    return n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
  }
};

TEST(ServiceNotifier, SendsToAnAbstractSocket) {
  Manager manager;
  const auto notifier = ServiceNotifier::from_environment();
  ASSERT_TRUE(notifier.active());
  EXPECT_TRUE(notifier.send("READY=1\nSTATUS=up"));
  EXPECT_EQ(manager.next(), "READY=1\nSTATUS=up");
}

TEST(ServiceNotifier, InactiveWithoutAUsableSocket) {
  ::unsetenv("NOTIFY_SOCKET");
  EXPECT_FALSE(ServiceNotifier::from_environment().active());
  ::setenv("NOTIFY_SOCKET", "relative/path", 1);
  EXPECT_FALSE(ServiceNotifier::from_environment().active());
  ::unsetenv("NOTIFY_SOCKET");
}

TEST(ServiceNotifier, PingsEveryHalfWatchdogPeriod) {
  Manager manager;
  ::setenv("WATCHDOG_USEC", "1000000", 1);
  ::setenv("WATCHDOG_PID", std::to_string(::getpid()).c_str(), 1);
  auto notifier = ServiceNotifier::from_environment();
  EXPECT_EQ(notifier.watchdog_ns(), 1'000'000'000);
  constexpr std::int64_t kMs = 1'000'000;
  int pings = 0;
  for (std::int64_t t = 0; t <= 2000; t += 40) {  // 25 Hz ticks for 2 s
    notifier.watchdog(t * kMs);
    while (manager.next() == "WATCHDOG=1") ++pings;
  }
  EXPECT_EQ(pings, 4);  // at 0, 520, 1040, 1560 ms
}

TEST(ServiceNotifier, AWatchdogForAnotherProcessIsNotOurs) {
  Manager manager;
  ::setenv("WATCHDOG_USEC", "1000000", 1);
  ::setenv("WATCHDOG_PID", "1", 1);
  EXPECT_EQ(ServiceNotifier::from_environment().watchdog_ns(), 0);
  ::setenv("WATCHDOG_PID", std::to_string(::getpid()).c_str(), 1);
  ::setenv("WATCHDOG_USEC", "soon", 1);
  EXPECT_EQ(ServiceNotifier::from_environment().watchdog_ns(), 0);
}

TEST(ServiceNotifier, AManagerThatDoesNotReadNeverBlocks) {
  Manager manager;
  const auto notifier = ServiceNotifier::from_environment();
  int sent = 0;
  for (int i = 0; i < 5000; ++i) sent += notifier.send("WATCHDOG=1") ? 1 : 0;  // returns: it never waits
  EXPECT_LT(sent, 5000);  // the queue filled: the rest were dropped
}

}  // namespace
}  // namespace andros
