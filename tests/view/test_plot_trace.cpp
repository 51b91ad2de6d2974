// The drive line draws the frames that went out and nothing else
// (view/plot_page.hpp, trace): a session's line, drawn 200, 800 and 1600 px
// wide over the whole drive and over parts of it, read back point by point
// and compared with the ticks its records stand for (each frame holding
// until the next tick's).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "andros/view/plot.hpp"
#include "view/plot_page.hpp"

namespace andros::view {
namespace {

constexpr std::size_t kDrive = 7;  // the byte a frame record's data holds drive in (frame signals)
constexpr int kNeutral = 128;

record::FrameRecord frame(std::int64_t tick, int drive, std::int64_t gap = 0,
                          link::SendResult result = link::SendResult::kSent) {
  record::FrameRecord f{.tick = tick, .t_ms = tick * 40, .result = result, .gap = gap};
  f.data[kDrive] = static_cast<std::uint8_t>(drive);
  return f;
}

/// A 28 s drive at 25 Hz, as a session records it (a record a change): full
/// drive from 1 s, stopped at 5.68 s (neutral to the end but for what
/// follows), a second of moves on every tick from 12 s, a stall of ten ticks
/// at 16 s, the link busy for five ticks at 17 s.
record::Session drive_session() {
  record::Session s;
  s.settings.rate_millihertz = 25'000;
  s.frames = {frame(0, kNeutral), frame(25, 255), frame(142, kNeutral)};
  for (std::int64_t k = 300; k < 325; ++k) s.frames.push_back(frame(k, static_cast<int>((k * 97) % 256)));
  s.frames.push_back(frame(325, kNeutral));
  s.frames.push_back(frame(410, 200, 10));  // ticks 400 to 409 were not run
  s.frames.push_back(frame(425, kNeutral, 0, link::SendResult::kBusy));
  s.frames.push_back(frame(430, kNeutral));
  s.end = record::EndRecord{.t_ms = 28'000, .last_tick = 700, .frames_sent = 690, .why = "SIGINT"};
  return s;
}

/// A tick that ran: its time and its drive (-1: nothing sent).
struct Tick {
  std::int64_t t_ms;
  std::int64_t tick;
  int drive;
};

/// Every tick the records stand for, read from them here (not by plot_samples).
std::vector<Tick> ticks_of(const record::Session& s) {
  std::vector<Tick> out;
  for (std::size_t i = 0; i < s.frames.size(); ++i) {
    const auto& f = s.frames[i];
    const auto last = i + 1 < s.frames.size() ? s.frames[i + 1].tick - s.frames[i + 1].gap - 1 : s.end->last_tick;
    for (auto k = f.tick; k <= last; ++k) {
      out.push_back({k * 40, k, f.result == link::SendResult::kSent ? static_cast<int>(f.data[kDrive]) : -1});
    }
  }
  return out;
}

struct Point {
  int column;
  int value;
};

/// The path's lines, each its points; y turned back into a value.
std::vector<std::vector<Point>> lines_of(const std::string& d) {
  std::vector<std::vector<Point>> lines;
  std::istringstream in(d);
  std::string word;
  while (in >> word) {
    if (word[0] == 'M') lines.emplace_back();
    const int x = std::stoi(word.substr(1));
    double y = 0;
    in >> y;
    const double v = (plot_detail::kDriveTop + plot_detail::kDriveHeight - y) * 255 / plot_detail::kDriveHeight;
    lines.back().push_back({x, static_cast<int>(std::lround(v))});
  }
  return lines;
}

/// The page from from_ms to to_ms, width px wide: the drive line checked
/// against the ticks.
void check(const record::Session& s, int width, std::int64_t from_ms, std::int64_t to_ms) {
  SCOPED_TRACE(fmt::format("{} px, {} to {} ms", width, from_ms, to_ms));
  const auto samples = plot_samples(s);
  const plot_detail::Page page(from_ms, to_ms, 0, width);
  const auto end = std::min(to_ms, samples.back().t_ms);
  const auto lines = lines_of(plot_detail::trace(page, plot_detail::window(samples, page), end, kDrive));
  const auto column = [&page](std::int64_t t) { return static_cast<int>(std::lround(page.x(t))); };

  // What held in each column, in time order, and the runs of ticks that sent.
  const auto ticks = ticks_of(s);
  std::vector<std::map<int, std::vector<int>>> held;
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    const auto& k = ticks[i];
    const bool next_runs = i + 1 < ticks.size() && ticks[i + 1].tick == k.tick + 1;
    const std::int64_t until = i + 1 == ticks.size() ? k.t_ms : next_runs ? ticks[i + 1].t_ms : (k.tick + 1) * 40;
    if (until < from_ms || (until == from_ms && until != k.t_ms) || k.t_ms > end) continue;
    if (k.drive < 0) {
      if (!held.empty() && !held.back().empty()) held.emplace_back();
      continue;
    }
    if (held.empty()) held.emplace_back();
    for (int c = column(std::max(k.t_ms, from_ms)); c <= column(std::min(until, end)); ++c) {
      auto& values = held.back()[c];
      if (values.empty() || values.back() != k.drive) values.push_back(k.drive);
    }
    if (!next_runs && i + 1 < ticks.size()) held.emplace_back();  // a stall: nothing went out
  }
  while (!held.empty() && held.back().empty()) held.pop_back();

  EXPECT_EQ(lines.size(), held.size()) << "a line for each run of ticks that sent, broken where none did";
  for (std::size_t n = 0; n < std::min(lines.size(), held.size()); ++n) {
    const auto& line = lines[n];
    const auto& cols = held[n];
    EXPECT_EQ(line.front().column, cols.begin()->first) << "line " << n << " starts where its frames do";
    EXPECT_EQ(line.back().column, cols.rbegin()->first) << "line " << n << " ends where its frames do";
    std::size_t at_in_column = 0;  // how far into the column's values the points have come
    for (std::size_t i = 0; i < line.size(); ++i) {
      const auto [c, v] = line[i];
      ASSERT_TRUE(cols.contains(c)) << "a point at column " << c << ", where no frame held";
      const auto& values = cols.at(c);
      if (i > 0 && c == line[i - 1].column) {
        // Within a column, the values in the order they held.
        while (at_in_column < values.size() && values[at_in_column] != v) ++at_in_column;
        EXPECT_LT(at_in_column, values.size()) << "column " << c << ": " << v << " drawn out of time order";
        continue;
      }
      if (i > 0) {
        ASSERT_GT(c, line[i - 1].column) << "point " << i << ": not in time order";
        EXPECT_EQ(v, line[i - 1].value) << "a slope from column " << line[i - 1].column << " to " << c;
        for (int between = line[i - 1].column + 1; between < c; ++between) {
          const auto crossed = cols.find(between);
          EXPECT_TRUE(crossed != cols.end() && crossed->second == std::vector<int>{v})
              << "level at " << v << " across column " << between;
        }
      }
      at_in_column = 0;
      while (at_in_column < values.size() && values[at_in_column] != v) ++at_in_column;
      EXPECT_LT(at_in_column, values.size()) << "column " << c << ": " << v << " never held in it";
    }
    // Each column drawn shows its lowest and highest value: no spike lost.
    for (const auto& [c, values] : cols) {
      std::set<int> drawn;
      for (const auto& p : line) {
        if (p.column == c) drawn.insert(p.value);
      }
      if (drawn.empty()) continue;  // crossed level (checked above)
      EXPECT_TRUE(drawn.contains(*std::min_element(values.begin(), values.end()))) << "column " << c;
      EXPECT_TRUE(drawn.contains(*std::max_element(values.begin(), values.end()))) << "column " << c;
    }
  }
}

TEST(PlotTrace, TheLineIsTheFramesSentInTimeOrderAtEveryWidthAndRange) {
  const auto s = drive_session();
  for (const int width : {200, 800, 1600}) {
    check(s, width, 0, 28'000);       // the whole: a tick 0.29, 1.1 and 2.3 px wide
    check(s, width, 5'000, 7'000);    // the stop
    check(s, width, 3'000, 9'000);    // starts inside the full drive, ends inside the neutral hold
    check(s, width, 11'900, 13'100);  // the moves, a tick 6.7 to 53 px
    check(s, width, 15'500, 18'000);  // the stall and the busy link: breaks
    check(s, width, 20'000, 40'000);  // ends past the last tick
  }
}

TEST(PlotTrace, AfterTheStopTheLineStaysNeutral) {
  const auto s = drive_session();
  for (const int width : {200, 800, 1600}) {
    const auto samples = plot_samples(s);
    const plot_detail::Page page(0, 28'000, 0, width);
    const auto lines = lines_of(plot_detail::trace(page, plot_detail::window(samples, page), 28'000, kDrive));
    const int stop = static_cast<int>(std::lround(page.x(5'680)));    // the first neutral frame
    const int moves = static_cast<int>(std::lround(page.x(11'960)));  // the last neutral tick before the moves
    for (const auto& p : lines.front()) {
      if (p.column > stop && p.column <= moves) {
        EXPECT_EQ(p.value, kNeutral) << width << " px, column " << p.column;
      }
    }
  }
}

}  // namespace
}  // namespace andros::view
