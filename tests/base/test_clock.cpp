// The periodic schedule every loop keeps: exact tick times, and missed ticks skipped.
#include <gtest/gtest.h>

#include "andros/base/clock.hpp"

namespace andros {
namespace {

TEST(TickGrid, TicksFallOnExactMultiplesOfThePeriod) {
  constexpr auto grid = TickGrid::every(40 * kNsPerMs);
  EXPECT_EQ(grid.tick_ns(0), 0);
  EXPECT_EQ(grid.tick_ns(3), 120 * kNsPerMs);
  // 30 ticks in a second: 33.3 ms each, rounded down per tick, never accumulated.
  constexpr TickGrid thirty(kNsPerSecond, 30);
  EXPECT_EQ(thirty.tick_ns(1), 33'333'333);
  EXPECT_EQ(thirty.tick_ns(30), kNsPerSecond);
  EXPECT_EQ(thirty.tick_ns(30 * 3600), 3600 * kNsPerSecond);
}

TEST(TickGrid, TheDueTickIsTheLatestWhoseTimeHasCome) {
  constexpr auto grid = TickGrid::every(40 * kNsPerMs);
  EXPECT_EQ(grid.due(-5), 0);  // before the start: the first tick
  EXPECT_EQ(grid.due(0), 0);
  EXPECT_EQ(grid.due(40 * kNsPerMs - 1), 0);
  EXPECT_EQ(grid.due(40 * kNsPerMs), 1);
  constexpr TickGrid thirty(kNsPerSecond, 30);
  // Tick times are rounded down to the ns: tick 7 is due from the ns after.
  EXPECT_EQ(thirty.due(thirty.tick_ns(7) + 1), 7);
  EXPECT_EQ(thirty.due(thirty.tick_ns(7) - 1), 6);
}

TEST(TickGrid, OnTimeTheNextTickFollows) {
  constexpr auto grid = TickGrid::every(10 * kNsPerMs);
  EXPECT_EQ(grid.next_tick(0, 1 * kNsPerMs), 1);
  EXPECT_EQ(grid.next_tick(4, 49 * kNsPerMs), 5);
  // Finished before its own time (a clock read early): still the next one, never the same tick twice.
  EXPECT_EQ(grid.next_tick(4, 0), 5);
}

TEST(TickGrid, AfterAStallTheMissedTicksAreSkipped) {
  constexpr auto grid = TickGrid::every(10 * kNsPerMs);
  // Tick 2 ended 75 ms in: 3..6 are missed, 7 is due now and runs at once; no burst.
  EXPECT_EQ(grid.next_tick(2, 75 * kNsPerMs), 7);
  // Late for one tick only: that tick runs, late; none is skipped.
  EXPECT_EQ(grid.next_tick(2, 31 * kNsPerMs), 3);
  // A day later the arithmetic holds.
  EXPECT_EQ(grid.next_tick(10, 86'400 * kNsPerSecond + 1), 100 * 86'400);
}

}  // namespace
}  // namespace andros
