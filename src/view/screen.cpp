#include "andros/view/screen.hpp"

#include <algorithm>
#include <numeric>

#include "andros/base/text.hpp"

namespace andros::view {
namespace {

bool continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

std::size_t code_points(std::string_view s) {
  return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) { return !continuation(c); }));
}

/// The first n code points of s.
std::string_view first(std::string_view s, std::size_t n) {
  std::size_t i = 0;
  for (; i < s.size(); ++i) {
    if (!continuation(s[i])) {
      if (n == 0) break;
      --n;
    }
  }
  return s.substr(0, i);
}

std::string_view sgr(Style style) {
  switch (style) {
    case Style::kPlain: return "";
    case Style::kBold: return "\x1b[1m";
    case Style::kDim: return "\x1b[2m";
    case Style::kReverse: return "\x1b[7m";
    case Style::kGood: return "\x1b[1;32m";
    case Style::kWarn: return "\x1b[1;33m";
    case Style::kAlert: return "\x1b[1;31m";
    case Style::kBanner: return "\x1b[1;97;41m";
  }
  return "";
}

/// Cuts the line's pieces to width; calls out(text, style) for each piece left.
template <typename Out>
void cut(const Line& line, std::size_t width, Out out) {
  std::size_t left = width;
  for (const auto& piece : line.pieces()) {
    if (left == 0) break;
    const auto text = first(piece.text, left);
    left -= code_points(text);
    out(text, piece.style);
  }
}

}  // namespace

Line& Line::add(std::string_view text, Style style) {
  // A control character would move the cursor: a name from a controller or
  // a file is shown, never obeyed (escaped as everywhere: base/text.hpp).
  pieces_.push_back(Piece{printable_line(text), style});
  return *this;
}

std::size_t Line::width() const {
  std::size_t n = 0;
  for (const auto& p : pieces_) n += code_points(p.text);
  return n;
}

void Screen::block(std::vector<Line> lines, int priority, bool may_shrink) {
  blocks_.push_back(Block{std::move(lines), priority, may_shrink});
}

void Screen::tail(std::vector<Line> lines, int priority) {
  blocks_.push_back(Block{std::move(lines), priority, true, true});
}

std::vector<Line> Screen::fit(TermSize size) const {
  const auto rows = static_cast<std::size_t>(std::max(size.rows, 1));
  std::vector<Line> out(pinned_.begin(), pinned_.begin() + static_cast<std::ptrdiff_t>(std::min(rows, pinned_.size())));
  std::size_t left = rows - out.size();
  std::vector<std::size_t> order(blocks_.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [this](std::size_t a, std::size_t b) { return blocks_[a].priority > blocks_[b].priority; });
  std::vector<std::size_t> shown(blocks_.size(), 0);  // lines of each block that fit
  for (const auto i : order) {
    const auto& b = blocks_[i];
    if (b.lines.size() <= left) {
      shown[i] = b.lines.size();
    } else if (b.may_shrink) {
      shown[i] = left;
    }
    left -= shown[i];
  }
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    const auto& lines = blocks_[i].lines;
    const auto skip = static_cast<std::ptrdiff_t>(blocks_[i].keep_last ? lines.size() - shown[i] : 0);
    out.insert(out.end(), lines.begin() + skip, lines.begin() + skip + static_cast<std::ptrdiff_t>(shown[i]));
  }
  return out;
}

std::string Screen::render(TermSize size, bool colour) const {
  const auto width = static_cast<std::size_t>(std::max(size.cols, 1));
  std::string out;
  for (const auto& line : fit(size)) {
    cut(line, width, [&](std::string_view text, Style style) {
      if (colour && style != Style::kPlain) {
        out += sgr(style);
        out += text;
        out += "\x1b[0m";
      } else {
        out += text;
      }
    });
    out += '\n';
  }
  return out;
}

std::string Screen::text() const {
  std::size_t rows = pinned_.size();
  for (const auto& b : blocks_) rows += b.lines.size();
  std::string out;
  for (const auto& line : fit({1, static_cast<int>(rows)})) {
    for (const auto& piece : line.pieces()) out += piece.text;
    out += '\n';
  }
  return out;
}

Screen text_screen(std::string_view text) {
  std::vector<Line> lines;
  for (std::size_t start = 0; start < text.size();) {
    const auto end = std::min(text.find('\n', start), text.size());
    lines.emplace_back(std::string(text.substr(start, end - start)));
    start = end + 1;
  }
  Screen screen;
  screen.block(std::move(lines), 1, true);
  return screen;
}

std::string plain(const Line& line, std::size_t width) {
  std::string out;
  cut(line, width, [&](std::string_view text, Style) { out += text; });
  return out;
}

std::vector<std::string> wrap_text(std::string_view text, std::size_t width, std::size_t indent) {
  indent = std::min(indent, width / 2);  // a continuation keeps room for text
  std::vector<std::string> out;
  std::string_view rest = text;
  std::size_t room = std::max<std::size_t>(width, 1);
  while (code_points(rest) > room) {
    auto head = first(rest, room);
    // Break after the last space that fits, when there is one past the indent.
    const auto space = head.rfind(' ');
    std::size_t next = head.size();
    if (space != std::string_view::npos && space > indent) {
      head = head.substr(0, space);
      next = space + 1;
    }
    out.emplace_back((out.empty() ? "" : std::string(indent, ' ')) + std::string(head));
    rest.remove_prefix(next);
    room = std::max<std::size_t>(width - indent, 1);
  }
  out.emplace_back((out.empty() ? "" : std::string(indent, ' ')) + std::string(rest));
  return out;
}

bool colour_wanted(const char* no_color, const char* term) {
  if (no_color != nullptr && no_color[0] != '\0') return false;
  if (term == nullptr) return false;
  const std::string_view t(term);
  constexpr std::string_view kMonochrome[] = {"", "dumb", "vt52", "vt100", "vt102", "vt220", "vt320", "ansi-mono"};
  return std::find(std::begin(kMonochrome), std::end(kMonochrome), t) == std::end(kMonochrome);
}

}  // namespace andros::view
