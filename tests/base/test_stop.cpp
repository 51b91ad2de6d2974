// ShutdownRequest: the one stop every loop checks, raised by code or by a stop
// signal, waking a loop that sleeps or waits on it. Bounds are generous: a
// woken wait ends in ms, a missed wake-up would take the full minute.
#include "andros/base/shutdown_request.hpp"

#include <gtest/gtest.h>
#include <pthread.h>
#include <unistd.h>

#include <thread>

#include "andros/base/clock.hpp"
#include "andros/base/unique_fd.hpp"

namespace andros {
namespace {

constexpr std::int64_t kLong = 60 * kNsPerSecond;
constexpr std::int64_t kWoken = 30 * kNsPerSecond;

TEST(ShutdownRequest, RaisedItStaysRequested) {
  ShutdownRequest stop;
  EXPECT_FALSE(stop.requested());
  stop.raise();
  EXPECT_TRUE(stop.requested());
  EXPECT_TRUE(stop.requested());
  EXPECT_EQ(stop.signal_number(), 0);  // code, not a signal
}

TEST(ShutdownRequest, SleepsToItsTimeWhenNothingAsks) {
  ShutdownRequest stop;
  const std::int64_t until = monotonic_ns() + 20 * kNsPerMs;
  EXPECT_TRUE(stop.sleep_until(until));
  EXPECT_GE(monotonic_ns(), until);
  EXPECT_TRUE(stop.sleep_until(0));  // a time already past: at once
}

TEST(ShutdownRequest, ARaiseFromAnotherThreadWakesASleeper) {
  ShutdownRequest stop;
  const std::int64_t start = monotonic_ns();
  std::thread raiser([&] {
    sleep_until_ns_uninterrupted(monotonic_ns() + 20 * kNsPerMs);
    stop.raise();
  });
  EXPECT_FALSE(stop.sleep_until(start + kLong));
  raiser.join();
  EXPECT_LT(monotonic_ns() - start, kWoken);
  EXPECT_FALSE(stop.sleep_until(start + kLong));  // and every sleep after it ends at once
}

TEST(ShutdownRequest, ARaiseEndsAWaitForInput) {
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const UniqueFd read_end(fds[0]);
  const UniqueFd write_end(fds[1]);
  ShutdownRequest stop;
  EXPECT_FALSE(stop.wait_readable(read_end.get(), monotonic_ns() + 10 * kNsPerMs));  // nothing yet: its time
  ASSERT_EQ(write(write_end.get(), "x", 1), 1);
  EXPECT_TRUE(stop.wait_readable(read_end.get(), kNoDeadline));

  char c = 0;
  ASSERT_EQ(read(read_end.get(), &c, 1), 1);
  const std::int64_t start = monotonic_ns();
  std::thread raiser([&] {
    sleep_until_ns_uninterrupted(monotonic_ns() + 20 * kNsPerMs);
    stop.raise();
  });
  EXPECT_FALSE(stop.wait_readable(read_end.get(), kNoDeadline));
  raiser.join();
  EXPECT_LT(monotonic_ns() - start, kWoken);
}

TEST(ShutdownRequest, ABlockedSignalBecomesARequest) {
  ShutdownRequest stop(kShutdownSignals);
  EXPECT_FALSE(stop.requested());
  raise(SIGTERM);  // blocked: pending, not fatal
  EXPECT_TRUE(stop.requested());
  EXPECT_EQ(stop.signal_number(), SIGTERM);
  EXPECT_TRUE(stop.requested());  // stays requested
}

TEST(ShutdownRequest, ASignalWakesASleeper) {
  ShutdownRequest stop(kShutdownSignals);
  const pthread_t sleeper = pthread_self();
  const std::int64_t start = monotonic_ns();
  // Sent to the sleeping thread itself: no other thread of the test binary can take it.
  std::thread sender([&] {
    sleep_until_ns_uninterrupted(monotonic_ns() + 20 * kNsPerMs);
    pthread_kill(sleeper, SIGINT);
  });
  EXPECT_FALSE(stop.sleep_until(start + kLong));
  sender.join();
  EXPECT_LT(monotonic_ns() - start, kWoken);
  EXPECT_EQ(stop.signal_number(), SIGINT);
}

TEST(ShutdownRequest, OnlyItsOwnSignalsAsk) {
  ShutdownRequest stop(kRecordShutdownSignals);
  ShutdownRequest code_only;
  raise(SIGINT);
  EXPECT_TRUE(stop.requested());
  EXPECT_FALSE(code_only.requested());
}

TEST(ShutdownRequest, AHangUpStopsUntilItIsMadeAReload) {
  {
    ShutdownRequest stop(kShutdownSignals);
    raise(SIGHUP);  // blocked: pending, not fatal
    EXPECT_TRUE(stop.requested());
    EXPECT_EQ(stop.signal_number(), SIGHUP);
  }
  ShutdownRequest stop(kShutdownSignals);
  stop.reload_on_hangup();
  raise(SIGHUP);
  EXPECT_FALSE(stop.requested());
  EXPECT_TRUE(stop.reload_requested());
  EXPECT_FALSE(stop.reload_requested());  // once per signal
  raise(SIGTERM);
  EXPECT_TRUE(stop.requested());
  EXPECT_EQ(stop.signal_number(), SIGTERM);
}

// The run loop's one look per tick: with nothing pending and nothing unread,
// stop, reload and job control have nothing to say, and are not asked.
TEST(ShutdownRequest, NothingPendingNothingUnreadMeansNothingNew) {
  ShutdownRequest stop(kShutdownSignals);
  stop.reload_on_hangup();
  EXPECT_FALSE(signals_pending());
  EXPECT_FALSE(stop.has_unread());
  raise(SIGHUP);  // blocked: pending
  EXPECT_TRUE(signals_pending());
  // Taken by another caller of requested() (a file read at start-up asks it):
  // no longer pending, but the reload is still to be read.
  EXPECT_FALSE(stop.requested());
  EXPECT_FALSE(signals_pending());
  EXPECT_TRUE(stop.has_unread());
  EXPECT_TRUE(stop.reload_requested());
  EXPECT_FALSE(stop.has_unread());
  stop.raise();
  EXPECT_TRUE(stop.has_unread());
  EXPECT_FALSE(signals_pending());
}

}  // namespace
}  // namespace andros
