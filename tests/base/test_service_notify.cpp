#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
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
  EXPECT_EQ(notifier.watchdog_ns(), kNsPerSecond);
  int pings = 0;
  for (std::int64_t t = 0; t <= 2000; t += 40) {  // 25 Hz ticks for 2 s
    notifier.watchdog(t * kNsPerMs);
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

TEST(ServiceNotifier, AWatchdogUsecThatIsNotANumberIsNone) {
  Manager manager;
  for (const char* text : {"", "soon", "-1", "+1000000", "1000000us", " 1000000", "0"}) {
    ::setenv("WATCHDOG_USEC", text, 1);
    EXPECT_EQ(ServiceNotifier::from_environment().watchdog_ns(), 0) << '"' << text << '"';
  }
}

// systemd's WATCHDOG_USEC is 64 bits unsigned: in ns, a period above ~9.2e15 us
// overflowed (and the pings stopped). Anything above a day is a day.
TEST(ServiceNotifier, AWatchdogPeriodAboveADayIsADay) {
  Manager manager;
  constexpr std::int64_t kDayUs = 86'400'000'000;
  const struct {
    const char* usec;
    std::int64_t ns;
  } cases[] = {
      {"1", 1'000},
      {"1000000", 1'000'000'000},
      {"86399999999", (kDayUs - 1) * 1'000},
      {"86400000000", ServiceNotifier::kMaxWatchdogNs},
      {"86400000001", ServiceNotifier::kMaxWatchdogNs},
      {"9223372036854775", ServiceNotifier::kMaxWatchdogNs},  // INT64_MAX ns, in us
      {"9300000000000000", ServiceNotifier::kMaxWatchdogNs},
      {"9223372036854775807", ServiceNotifier::kMaxWatchdogNs},
      {"18446744073709551615", ServiceNotifier::kMaxWatchdogNs},        // 2^64-1
      {"99999999999999999999999999", ServiceNotifier::kMaxWatchdogNs},  // beyond 64 bits: still a number
  };
  EXPECT_EQ(ServiceNotifier::kMaxWatchdogNs, kDayUs * 1'000);
  for (const auto& c : cases) {
    ::setenv("WATCHDOG_USEC", c.usec, 1);
    EXPECT_EQ(ServiceNotifier::from_environment().watchdog_ns(), c.ns) << c.usec;
  }
}

TEST(ServiceNotifier, AClampedWatchdogStillPingsEveryHalfPeriod) {
  Manager manager;
  constexpr std::int64_t kHalf = ServiceNotifier::kMaxWatchdogNs / 2;
  constexpr std::int64_t kLatest = std::numeric_limits<std::int64_t>::max();
  for (const char* usec : {"9300000000000000", "18446744073709551615"}) {
    ::setenv("WATCHDOG_USEC", usec, 1);
    auto notifier = ServiceNotifier::from_environment();
    std::string pings;
    // (now, whether it pings): the first at once, then every half day, up to the latest time there is.
    for (const std::int64_t now :
         {std::int64_t{0}, kHalf - 1, kHalf, 2 * kHalf - 1, 2 * kHalf, kLatest - kHalf, kLatest - 1, kLatest}) {
      notifier.watchdog(now);
      pings += manager.next() == "WATCHDOG=1" ? 'p' : '.';
    }
    EXPECT_EQ(pings, "p.p.pp.p") << usec;
  }
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
