// The drive and pivot lines (view/plot_page.hpp): what went out, in time
// order. A frame holds the vehicle's drive until the next tick's frame
// replaces it, so the line is a step: level from one frame to the next, then
// straight up or down to the new value, never a slope through values no
// frame had. Where many frames fall in one pixel column, the column keeps
// its first value, its lowest and highest, and its last, in the order they
// were sent: the line enters the column where the last one left it, spans
// every value sent in it, and leaves it at the value that held on.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "plot_page.hpp"

namespace andros::view::plot_detail {
namespace {

/// Writes a line's points as path data, at most four a pixel column.
class ColumnPoints {
 public:
  explicit ColumnPoints(std::string& path) : path_(path) {}

  /// The line moves to value at column, after every point before it.
  void add(int column, int value) {
    if (column != column_) {
      flush();
      column_ = column;
      first_ = last_ = lo_ = hi_ = Point{0, value};
      count_ = 1;
      return;
    }
    const Point p{count_++, value};
    if (value < lo_.value) lo_ = p;
    if (value > hi_.value) hi_ = p;
    last_ = p;
  }

  /// The line ends: the next point starts a new one.
  void end_line() {
    flush();
    starting_ = true;
  }

 private:
  struct Point {
    int at = 0;  // its place among the column's points: their time order
    int value = 0;
  };

  void flush() {
    if (column_ == kNone) return;
    std::array<Point, 4> points{first_, lo_, hi_, last_};
    std::stable_sort(points.begin(), points.end(), [](const Point& a, const Point& b) { return a.at < b.at; });
    int drawn = kNone;
    for (const auto& p : points) {
      if (p.value == drawn) continue;
      path_ += fmt::format("{}{} {:.1f}", starting_ ? (path_.empty() ? "M" : " M") : " L", column_, value_y(p.value));
      starting_ = false;
      drawn = p.value;
    }
    column_ = kNone;
  }

  static constexpr int kNone = std::numeric_limits<int>::min();
  std::string& path_;
  bool starting_ = true;
  int column_ = kNone;
  int count_ = 0;
  Point first_;
  Point lo_;
  Point hi_;
  Point last_;
};

}  // namespace

std::string trace(const Page& page, const std::vector<const PlotSample*>& s, std::int64_t end, std::size_t byte) {
  std::string path;
  ColumnPoints points(path);
  const auto column = [&page](std::int64_t t) { return static_cast<int>(std::lround(page.x(t))); };
  bool open = false;  // a frame sent before this sample still holds
  int held = 0;
  for (const auto* p : s) {
    const int c = column(p->t_ms);
    if (open) points.add(c, held);  // what held until this tick
    if (!p->sent) {
      if (open) points.end_line();
      open = false;
      continue;
    }
    held = p->data[byte];
    points.add(c, held);
    open = true;
  }
  if (open) points.add(column(end), held);
  points.end_line();
  return path;
}

}  // namespace andros::view::plot_detail
