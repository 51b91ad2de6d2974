#include <gtest/gtest.h>

#include "andros/timing/tick_schedule.hpp"

namespace andros::timing {
namespace {

TEST(TickSchedule, TicksAreExactMultiplesOfThePeriod) {
  const TickSchedule s(25'000);
  EXPECT_EQ(s.tick_ns(1), 40'000'000);
  EXPECT_EQ(s.tick_ns(90'000), 3'600'000'000'000);                                     // one hour: no drift
  EXPECT_EQ(s.tick_ns(25LL * 86'400 * 365 * 10), 86'400LL * 365 * 10 * kNsPerSecond);  // ten years
  EXPECT_EQ(s.tick_ms(3), 120);
  const TickSchedule t(30'000);
  EXPECT_EQ(t.tick_ns(3), 100'000'000);  // no rounding carried from tick to tick
  EXPECT_EQ(t.tick_ms(1), 33);
  const TickSchedule half(12'500);
  EXPECT_EQ(half.tick_ns(1), 80'000'000);
  EXPECT_EQ(half.tick_ms(5), 400);
}

TEST(TickSchedule, OnTimeGoesToTheNextTick) {
  const TickSchedule s(25'000);
  EXPECT_EQ(s.next_tick(0, kNsPerMs), 1);
  EXPECT_EQ(s.next_tick(4, 4 * 40'000'000 + 39'000'000), 5);
}

TEST(TickSchedule, AfterAStallSkipsToTheLatestDueTick) {
  const TickSchedule s(25'000);
  // Tick 2 finished 250 ms in: ticks 3..5 are missed, 6 is due now; no burst.
  EXPECT_EQ(s.next_tick(2, 250'000'000), 6);
  // Just late for one tick: that tick runs (late), none skipped.
  EXPECT_EQ(s.next_tick(2, 121 * kNsPerMs), 3);
  // After a day's suspend, the arithmetic still holds.
  EXPECT_EQ(s.next_tick(10, 86'400'000'000'000 + 1), 25 * 86'400);
}

}  // namespace
}  // namespace andros::timing
