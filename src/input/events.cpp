#include "andros/input/events.hpp"

#include <cstdio>
#include <string_view>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"

namespace andros::input {
namespace {

struct Token {
  std::string_view text;
  int column;  // 1-based
};

std::vector<Token> split(std::string_view line) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i >= line.size()) break;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    tokens.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
  }
  return tokens;
}

constexpr std::string_view kSupervisorWord = "supervisor";

/// The events a controller makes: the ones `supervisor` may come before.
bool is_pad_event(std::string_view word) {
  return word == "connect" || word == "disconnect" || word == "button" || word == "axis" || word == "hat";
}

constexpr std::array<std::pair<std::string_view, int>, 9> kHatValues = {{
    {"centered", 0},
    {"up", 1},
    {"right", 2},
    {"down", 4},
    {"left", 8},
    {"rightup", 3},
    {"rightdown", 6},
    {"leftup", 9},
    {"leftdown", 12},
}};

/// A controller's name as a `connect` line holds it: printable_text() (a
/// newline in a device's name never starts another event), and `#`, which
/// would start a comment, and a space at either end, which the reader trims,
/// as \x23 and \x20.
std::string script_name(std::string_view name) {
  std::string out;
  for (const char c : printable_text(name)) out += c == '#' ? std::string("\\x23") : std::string(1, c);
  if (out.starts_with(' ')) out.replace(0, 1, "\\x20");
  if (out.starts_with('{')) out.replace(0, 1, "\\x7b");  // a brace first begins the pad's identity
  if (out.ends_with(' ')) out.replace(out.size() - 1, 1, "\\x20");
  return out;
}

}  // namespace

std::optional<InputEvent> EventReader::next() {
  using T = InputEvent::Type;
  while (const auto raw = text_.next_line()) {
    std::string_view line = *raw;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    const auto tokens = split(line);
    if (tokens.empty()) continue;

    const auto at = [&](const Token& t) { return SourcePos{text_.name(), text_.line_number(), t.column}; };
    const auto fail = [&](const Token& t, const std::string& what) -> InputError { return InputError(at(t), what); };
    if (ended_) throw fail(tokens[0], "event after 'end'");

    InputEvent ev;
    ev.line = text_.line_number();
    ev.t_ms = parse_integer(tokens[0].text, 0, INT64_MAX / 2, "time", at(tokens[0]));
    if (ev.t_ms > kMaxScriptMs) {
      throw fail(tokens[0], "time " + std::to_string(ev.t_ms) + " ms is past 24 h (" + std::to_string(kMaxScriptMs) +
                                " ms), the longest an event script may last");
    }
    if (ev.t_ms < last_t_) {
      throw fail(tokens[0], "time " + std::to_string(ev.t_ms) + " ms goes backwards (previous event at " +
                                std::to_string(last_t_) + " ms)");
    }
    if (tokens.size() < 2) throw fail(tokens[0], "missing event after the time");
    // `T supervisor EVENT ARGS`: the supervisor's controller; the event's words follow.
    std::size_t first = 1;
    if (tokens[1].text == kSupervisorWord) {
      ev.pad = Pad::kSupervisor;
      first = 2;
      if (tokens.size() < 3) throw fail(tokens[1], "missing event after 'supervisor'");
    }
    const auto& kind = tokens[first];
    // The event's own words: arg(1) is the first after its name.
    const auto arg = [&](std::size_t i) -> const Token& { return tokens[first + i]; };
    const auto want_args = [&](std::size_t n, const char* usage) {
      if (tokens.size() != first + n + 1) {
        const auto& where = tokens.size() > first + n + 1 ? arg(n + 1) : kind;
        throw fail(where, std::string("expected '") + usage + "'");
      }
    };
    if (ev.pad == Pad::kSupervisor && !is_pad_event(kind.text)) {
      throw fail(kind, "'supervisor' takes connect, disconnect, button, axis or hat, not " + quote(kind.text) +
                           ": the other events are the run's, not a controller's");
    }

    if (kind.text == "connect") {
      ev.type = T::kConnect;
      if (tokens.size() > first + 1) {
        // The name as format_event writes it: one line of printable text, escaped (docs/event-scripts.md).
        auto written = std::string(line.substr(static_cast<std::size_t>(arg(1).column - 1)));
        while (!written.empty() && (written.back() == ' ' || written.back() == '\t' || written.back() == '\r')) {
          written.pop_back();
        }
        // `{path=P serial=S guid=G}` first: which physical pad (PadIdentity::fields()).
        if (written.starts_with('{')) {
          const auto close = written.find('}');
          PadIdentity id;
          if (close == std::string::npos || !parse_pad_fields(written.substr(1, close - 1), id)) {
            throw fail(arg(1), "a pad's identity is {path=P serial=S guid=G} (each optional, escaped as names are)");
          }
          ev.device = id.fields();
          written.erase(0, close + 1);
          while (written.starts_with(' ')) written.erase(0, 1);
        }
        if (!is_printable_line(written)) {
          throw fail(arg(1),
                     "controller name " + quote(written) +
                         " is not one line of printable text (a control byte or invalid UTF-8 is written \\xNN)");
        }
        ev.name = unescape_text(written, at(arg(1)));
        if (ev.name.size() > kMaxControllerNameBytes) {
          throw fail(arg(1), "controller name longer than " + std::to_string(kMaxControllerNameBytes) + " bytes");
        }
      }
    } else if (kind.text == "disconnect") {
      want_args(0, "disconnect");
      ev.type = T::kDisconnect;
    } else if (kind.text == "end") {
      want_args(0, "end");
      ev.type = T::kEnd;
      ended_ = true;
    } else if (kind.text == "button") {
      want_args(2, "button NAME 0|1");
      ev.type = T::kButton;
      const auto key = parse_button_name(arg(1).text);
      if (!key || key->kind == InputKind::kHat) {
        throw fail(arg(1), "unknown button " + quote(arg(1).text));
      }
      ev.key = *key;
      ev.value = static_cast<int>(parse_integer(arg(2).text, 0, 1, "button value", at(arg(2))));
    } else if (kind.text == "axis") {
      want_args(2, "axis NAME VALUE");
      ev.type = T::kAxis;
      const auto key = parse_axis_name(arg(1).text);
      if (!key) throw fail(arg(1), "unknown axis " + quote(arg(1).text));
      ev.key = *key;
      ev.value = static_cast<int>(parse_integer(arg(2).text, kAxisMin, kAxisMax, "axis value", at(arg(2))));
    } else if (kind.text == "hat") {
      want_args(2, "hat N centered|up|down|left|right|leftup|leftdown|rightup|rightdown");
      ev.type = T::kHat;
      const auto hat = parse_integer(arg(1).text, 0, kMaxHatIndex, "hat number", at(arg(1)));
      ev.key = InputKey{InputKind::kHat, static_cast<std::uint16_t>(hat * 4)};
      bool found = false;
      for (const auto& [name, mask] : kHatValues) {
        if (name == arg(2).text) {
          ev.value = mask;
          found = true;
        }
      }
      if (!found) throw fail(arg(2), "unknown hat position " + quote(arg(2).text));
    } else if (kind.text == "link") {
      want_args(1, "link down|up|taken|stalled|reading");
      const auto& what = arg(1).text;
      if (what == "down") {
        ev.type = T::kLinkDown;
      } else if (what == "up") {
        ev.type = T::kLinkUp;
      } else if (what == "taken") {
        ev.type = T::kLinkTaken;
      } else if (what == "stalled") {
        ev.type = T::kLinkStalled;
      } else if (what == "reading") {
        ev.type = T::kLinkReading;
      } else {
        throw fail(arg(1), "unknown link event " + quote(what) + " (expected down, up, taken, stalled or reading)");
      }
    } else if (kind.text == "suspend") {
      want_args(0, "suspend");
      ev.type = T::kSuspend;
    } else if (kind.text == "resume") {
      want_args(0, "resume");
      ev.type = T::kResume;
    } else if (kind.text == "stop") {
      want_args(0, "stop");
      ev.type = T::kShutdown;
    } else if (kind.text == "reload") {
      if (tokens.size() > first + 2) throw fail(arg(2), "expected 'reload [MAPPING]'");
      ev.type = T::kReload;
      if (tokens.size() == first + 2) ev.name = std::string(arg(1).text);
    } else {
      throw fail(kind, "unknown event " + quote(kind.text) +
                           " (expected connect, disconnect, button, axis, hat, end, link, suspend, resume, "
                           "reload, stop or supervisor)");
    }
    last_t_ = ev.t_ms;
    return ev;
  }
  return std::nullopt;
}

std::vector<InputEvent> parse_event_script(const std::string& text, const std::string& file_name) {
  TextReader in(text, file_name, kEventScriptLimits);
  EventReader reader(in);
  std::vector<InputEvent> events;
  while (auto ev = reader.next()) events.push_back(std::move(*ev));
  return events;
}

TextReader checked_event_script(TextReader text) {
  if (!text.can_rewind()) text = hold_in_memory(std::move(text));
  EventReader reader(text);
  while (reader.next()) {
  }
  text.rewind();
  return text;
}

bool addresses_supervisor(TextReader& text) {
  bool found = false;
  try {
    while (const auto raw = text.next_line()) {
      std::string_view line = *raw;
      if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
      const auto tokens = split(line);
      if (tokens.size() >= 2 && tokens[1].text == kSupervisorWord) {
        found = true;
        break;
      }
    }
  } catch (const InputError&) {
    // A line over the limits: the script fails there when it is played.
  }
  text.rewind();
  return found;
}

std::string format_event(const InputEvent& event) {
  using T = InputEvent::Type;
  char head[32];
  std::snprintf(head, sizeof head, "%-7lld ", static_cast<long long>(event.t_ms));
  std::string out = head;
  if (event.pad == Pad::kSupervisor) out += std::string(kSupervisorWord) + ' ';
  const auto pad = [](std::string word) {
    word.resize(std::max<std::size_t>(word.size(), 11), ' ');
    return word + ' ';
  };
  switch (event.type) {
    case T::kConnect:
      out += (event.name.empty() && event.device.empty())
                 ? "connect"
                 : pad("connect") + (event.device.empty() ? "" : "{" + event.device + "} ") +
                       script_name(event.name.substr(0, kMaxControllerNameBytes));
      break;
    case T::kDisconnect: out += "disconnect"; break;
    case T::kEnd: out += "end"; break;
    case T::kLinkDown: out += "link down"; break;
    case T::kLinkUp: out += "link up"; break;
    case T::kLinkTaken: out += "link taken"; break;
    case T::kLinkStalled: out += "link stalled"; break;
    case T::kLinkReading: out += "link reading"; break;
    case T::kSuspend: out += "suspend"; break;
    case T::kResume: out += "resume"; break;
    case T::kShutdown: out += "stop"; break;
    case T::kReload: out += event.name.empty() ? "reload" : pad("reload") + event.name; break;
    case T::kButton: out += pad("button") + input_name(event.key) + ' ' + std::to_string(event.value); break;
    case T::kAxis: out += pad("axis") + input_name(event.key) + ' ' + std::to_string(event.value); break;
    case T::kHat: {
      std::string_view position = "centered";
      for (const auto& [name, mask] : kHatValues) {
        if (mask == event.value) position = name;
      }
      out += pad("hat") + std::to_string(event.key.index / 4) + ' ' + std::string(position);
      break;
    }
  }
  return out;
}

}  // namespace andros::input
