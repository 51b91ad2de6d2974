#pragma once
/// A screen that fits the terminal: lines made of styled pieces, the pinned
/// ones always shown (in order, at the top), then blocks by priority while
/// rows are left; a line wider than the terminal wraps under itself. Never more lines than the
/// terminal has, so the screen never scrolls the header away.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace andros::view {

struct TermSize {
  int cols = 80;
  int rows = 24;
};

enum class Style : std::uint8_t {
  kPlain,
  kBold,
  kDim,
  kReverse,
  kGood,    ///< green: enabled, link up
  kWarn,    ///< yellow: connecting, held back
  kAlert,   ///< red: not enabled, link down
  kBanner,  ///< white on red, bold: WEAPONS ENABLED
};

struct Piece {
  std::string text;
  Style style = Style::kPlain;
};

/// One line of the screen.
class Line {
 public:
  Line() = default;
  Line(std::string_view text, Style style = Style::kPlain) { add(text, style); }  // NOLINT: implicit by design
  Line& add(std::string_view text, Style style = Style::kPlain);
  [[nodiscard]] const std::vector<Piece>& pieces() const { return pieces_; }
  /// Characters shown (UTF-8 code points; escape sequences are never in a piece).
  [[nodiscard]] std::size_t width() const;
  /// Where the line's continuations start when it wraps (spaces): under its
  /// text, past a label such as "state       ".
  Line& hang(std::size_t spaces) {
    hang_ = spaces;
    return *this;
  }
  [[nodiscard]] std::size_t hang() const { return hang_; }
  /// A line that is cut at the edge instead of wrapped: a banner whose first
  /// words say it all, kept to one row on the smallest terminal.
  Line& one_row() {
    one_row_ = true;
    return *this;
  }
  [[nodiscard]] bool is_one_row() const { return one_row_; }

 private:
  std::vector<Piece> pieces_;
  std::size_t hang_ = 2;
  bool one_row_ = false;
};

class Screen {
 public:
  /// Shown whatever the size, top first (cut to the rows if there are more).
  void pin(Line line) { pinned_.push_back(std::move(line)); }
  /// Shown while rows are left, higher priority first, at their place in the
  /// order they were added. A block shows whole or, when it may shrink, its first lines.
  void block(std::vector<Line> lines, int priority, bool may_shrink = false);
  /// A block that, shrunk, keeps its last lines (the newest of a log).
  void tail(std::vector<Line> lines, int priority);
  /// Exactly min(rows, lines) lines (a wrapped line counts each of its
  /// parts), '\n'-terminated, none wider than cols; with colour, ANSI SGR
  /// sequences (each line ends with a reset).
  [[nodiscard]] std::string render(TermSize size, bool colour) const;
  /// The lines that fit, wrapped to the width, for tests and off-terminal use.
  [[nodiscard]] std::vector<Line> fit(TermSize size) const;
  /// Every line, plain and whole: the screen printed to a file or pipe.
  [[nodiscard]] std::string text() const;

 private:
  struct Block {
    std::vector<Line> lines;
    int priority;
    bool may_shrink;
    bool keep_last = false;
  };
  [[nodiscard]] std::vector<Line> fit(TermSize size, bool wrap) const;

  std::vector<Line> pinned_;
  std::vector<Block> blocks_;
};

/// A screen of plain text lines, one block that shrinks to its first lines.
Screen text_screen(std::string_view text);

/// The plain text of a line cut to width (no escapes).
std::string plain(const Line& line, std::size_t width);

/// text as lines of at most width characters (UTF-8 code points), broken at
/// spaces where it can and inside a word longer than a line; every line
/// after the first starts with indent spaces. Nothing is left out.
std::vector<std::string> wrap_text(std::string_view text, std::size_t width, std::size_t indent);

/// text cut in its middle to at most room characters (UTF-8 code points),
/// "..." where it was cut: a third of what is kept from its start, two from
/// its end (a path's file name, a by-id path's serial number). Left whole
/// when room is too small for that to say anything.
std::string cut_middle(std::string_view text, std::size_t room);

/// line as lines of at most width characters, broken as wrap_text breaks
/// its text, each piece keeping its style; continuations start line.hang()
/// spaces in.
std::vector<Line> wrap_line(const Line& line, std::size_t width);

/// Whether to use colour on this terminal: not with NO_COLOR set (any value,
/// https://no-color.org), not for TERM unset, "dumb" or a terminal type
/// known to have none (vt100, vt220, ...).
bool colour_wanted(const char* no_color, const char* term);

}  // namespace andros::view
