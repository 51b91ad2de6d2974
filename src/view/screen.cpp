#include "andros/view/screen.hpp"

#include <algorithm>
#include <numeric>

#include "andros/base/sink_text.hpp"

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
  // a file is shown, never obeyed (escaped as on every sink: base/sink_text.hpp).
  pieces_.push_back(Piece{terminal_line(text), style});
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

std::vector<Line> Screen::fit(TermSize size) const { return fit(size, true); }

std::vector<Line> Screen::fit(TermSize size, bool wrap) const {
  const auto rows = static_cast<std::size_t>(std::max(size.rows, 1));
  const auto width = static_cast<std::size_t>(std::max(size.cols, 1));
  // Every line wider than the screen wraps under itself: what a line says is
  // never cut off at the edge, only a block that does not fit is left out.
  const auto wrapped = [&](const std::vector<Line>& lines) {
    if (!wrap) return lines;
    std::vector<Line> out;
    for (const auto& line : lines) {
      auto parts = wrap_line(line, width);
      out.insert(out.end(), std::make_move_iterator(parts.begin()), std::make_move_iterator(parts.end()));
    }
    return out;
  };
  std::vector<Line> out = wrapped(pinned_);
  out.resize(std::min(rows, out.size()));
  std::size_t left = rows - out.size();
  std::vector<std::vector<Line>> blocks;
  blocks.reserve(blocks_.size());
  for (const auto& b : blocks_) blocks.push_back(wrapped(b.lines));
  std::vector<std::size_t> order(blocks_.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [this](std::size_t a, std::size_t b) { return blocks_[a].priority > blocks_[b].priority; });
  std::vector<std::size_t> shown(blocks_.size(), 0);  // lines of each block that fit
  for (const auto i : order) {
    if (blocks[i].size() <= left) {
      shown[i] = blocks[i].size();
    } else if (blocks_[i].may_shrink) {
      shown[i] = left;
    }
    left -= shown[i];
  }
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    const auto& lines = blocks[i];
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
  for (const auto& line : fit({1, static_cast<int>(rows)}, false)) {
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

namespace {

/// Where wrap_text breaks text: each line's byte range, the spaces it broke
/// at left out.
std::vector<std::pair<std::size_t, std::size_t>> wrap_ranges(std::string_view text, std::size_t width,
                                                             std::size_t indent) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  std::size_t at = 0;
  std::size_t room = std::max<std::size_t>(width, 1);
  while (code_points(text.substr(at)) > room) {
    auto head = first(text.substr(at), room);
    // Break at the space just past what fits, or after the last space that
    // fits (on the first line, one past the indent).
    const auto space = at + head.size() < text.size() && text[at + head.size()] == ' ' ? head.size() : head.rfind(' ');
    std::size_t next = head.size();
    if (space != std::string_view::npos && space > (out.empty() ? indent : 0)) {
      head = head.substr(0, space);
      next = space + 1;
    }
    out.emplace_back(at, at + head.size());
    at += next;
    room = std::max<std::size_t>(width - indent, 1);
  }
  out.emplace_back(at, text.size());
  return out;
}

}  // namespace

std::vector<std::string> wrap_text(std::string_view text, std::size_t width, std::size_t indent) {
  indent = std::min(indent, width / 2);  // a continuation keeps room for text
  std::vector<std::string> out;
  for (const auto& [from, to] : wrap_ranges(text, width, indent)) {
    out.emplace_back((out.empty() ? "" : std::string(indent, ' ')) + std::string(text.substr(from, to - from)));
  }
  return out;
}

std::string cut_middle(std::string_view text, std::size_t room) {
  constexpr std::string_view kCut = "...";
  const auto size = code_points(text);
  if (size <= room || room <= kCut.size() + 2) return std::string(text);
  const auto keep = room - kCut.size();
  const auto head = first(text, keep / 3);
  const auto tail = text.substr(first(text, size - (keep - keep / 3)).size());
  return std::string(head) + std::string(kCut) + std::string(tail);
}

std::vector<Line> wrap_line(const Line& line, std::size_t width) {
  if (line.width() <= width || line.is_one_row()) return {line};
  std::string text;
  for (const auto& piece : line.pieces()) text += piece.text;
  const auto indent = std::min(line.hang(), width / 2);
  std::vector<Line> out;
  for (const auto& [from, to] : wrap_ranges(text, width, indent)) {
    Line part(out.empty() ? "" : std::string(indent, ' '));
    part.hang(line.hang());
    std::size_t at = 0;  // the piece's start in text
    for (const auto& piece : line.pieces()) {
      const auto begin = std::max(from, at);
      const auto end = std::min(to, at + piece.text.size());
      if (begin < end) part.add(std::string_view(text).substr(begin, end - begin), piece.style);
      at += piece.text.size();
    }
    out.push_back(std::move(part));
  }
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
