// read_session (andros/record/session.hpp): the records back into what replay
// and plot need, each checked as it is read against what a session can hold:
// its ticks fall at the recorded rate's times, within a day.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>

#include "andros/base/clock.hpp"
#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "andros/input/events.hpp"
#include "andros/record/session.hpp"
#include "andros/timing/rate.hpp"
#include "session_lines.hpp"

namespace andros::record {
namespace {

/// The rates run sends at: 1 Hz up to what its fastest line carries (115,200 baud, 360 bits a frame).
constexpr std::int64_t kSlowestRate = timing::kMillihertzPerHz;
constexpr std::int64_t kFastestRate = std::int64_t{115'200} * timing::kMillihertzPerHz / timing::kBitsPerFrame;

/// Fields of a record's payload after SEQ and KIND.
class Fields {
 public:
  Fields(std::string_view text, SourcePos pos) : text_(text), pos_(std::move(pos)) {}
  std::string_view word() {
    const auto start = text_.find_first_not_of(' ');
    if (start == std::string_view::npos) throw InputError(pos_, "record ends early");
    text_.remove_prefix(start);
    const auto end = text_.find(' ');
    const auto w = text_.substr(0, end);
    text_.remove_prefix(end == std::string_view::npos ? text_.size() : end);
    return w;
  }
  std::int64_t integer() {
    const auto w = word();
    const auto v = to_integer(w);
    if (!v) throw InputError(pos_, "expected a number, got " + quote(w));
    return *v;
  }
  /// The rest, after one space.
  std::string_view rest() { return text_.empty() ? text_ : text_.substr(1); }
  nlohmann::json json() {
    try {
      return nlohmann::json::parse(rest());
    } catch (const nlohmann::json::exception& e) {
      throw InputError(pos_, std::string("bad JSON: ") + e.what());
    }
  }
  [[nodiscard]] const SourcePos& pos() const { return pos_; }
  /// A JSON string of text from outside, as the session's format wrote it:
  /// from kEscapedTextFormat as printable_text() writes it (any bytes).
  std::string text(const nlohmann::json& j, int format) const {
    if (!j.is_string()) throw InputError(pos_, "expected a JSON string");
    return format >= kEscapedTextFormat ? unescape_text(j.get<std::string>(), pos_) : j.get<std::string>();
  }
  /// The rest as such a JSON string.
  std::string text(int format) { return text(json(), format); }

 private:
  std::string_view text_;
  SourcePos pos_;
};

/// A stop's or reset's pad: `{"name":..,"path":..,"serial":..,"guid":..}`,
/// each escaped as printable_text() writes it; earlier versions wrote a
/// stop's name alone as a JSON string, and nothing after a reset.
void read_stop_pad(Fields& f, StopRecord& r) {
  r.has_pad = false;
  if (f.rest().empty() && r.reset) return;
  const auto j = f.json();
  if (j.is_string() && !r.reset) {
    r.name = j.get<std::string>();
    r.pad.name = r.name;
    return;
  }
  r.has_pad = true;
  if (!j.is_object()) throw InputError(f.pos(), "a stop's pad is an object {\"name\": ..., \"path\": ...}");
  for (const auto& [key, field] :
       {std::pair{"name", &r.pad.name}, {"path", &r.pad.path}, {"serial", &r.pad.serial}, {"guid", &r.pad.guid}}) {
    const auto it = j.find(key);
    if (it == j.end() || !it->is_string())
      throw InputError(f.pos(), std::string("a stop's pad has no text '") + key + "'");
    *field = unescape_text(it->get<std::string>(), f.pos());
  }
  r.name = r.pad.name;
  if (const auto again = j.find("again"); again != j.end()) {
    if (!again->is_boolean() || r.reset) throw InputError(f.pos(), "a stop's 'again' is true or false, on a stop only");
    r.again = again->get<bool>();
  }
}

/// A record's time: -1 (before the first tick) up to kMaxSessionMs.
std::int64_t time(Fields& f) {
  const auto t = f.integer();
  if (t < -1 || t > kMaxSessionMs) {
    throw InputError(f.pos(), "time " + std::to_string(t) + " ms: not within a session (0 to 24 h)");
  }
  return t;
}

/// A tick and its time: the tick falls at that time at the session's rate, within kMaxSessionMs.
void check_tick(const Session& s, std::int64_t tick, std::int64_t t_ms, const SourcePos& pos) {
  if (s.settings.sources.empty()) throw InputError(pos, "a tick before the settings");
  const std::int64_t rate = s.settings.rate_millihertz;
  const timing::FrameClock clock(rate);
  const std::int64_t last = kMaxSessionMs * rate / (kMsPerSecond * timing::kMillihertzPerHz);
  if (tick < 0 || tick > last) {
    throw InputError(pos, "tick " + std::to_string(tick) + ": not within a session (0 to " + std::to_string(last) +
                              " at " + timing::rate_text(rate) + " Hz: 24 h)");
  }
  if (clock.time_of(tick) != t_ms) {
    throw InputError(pos, "tick " + std::to_string(tick) + " falls at " + std::to_string(clock.time_of(tick)) +
                              " ms at " + timing::rate_text(rate) + " Hz, not " + std::to_string(t_ms));
  }
}

SessionSettings parse_settings(const Fields& f, const nlohmann::json& j, int format) {
  const auto& pos = f.pos();
  const auto text = [&](const nlohmann::json& field) { return f.text(field, format); };
  try {
    SessionSettings s;
    s.robot = text(j.at("robot"));
    s.mapping_file = text(j.at("mapping"));
    // Format 1 wrote the same value as `rate_mhz`.
    s.rate_millihertz = j.at(j.contains("rate_millihertz") ? "rate_millihertz" : "rate_mhz").get<std::int64_t>();
    s.weapons = j.at("weapons").get<bool>();
    s.code = parse_code(j.at("code").get<std::string>(), pos);
    s.center = j.at("center").get<int>();
    s.port = text(j.at("port"));
    s.baud = j.at("baud").get<int>();
    s.input = text(j.at("input"));
    s.config = text(j.at("config"));
    s.supervised = j.value("supervised", false);
    for (const auto& file : j.at("files")) {
      MappingSource src{text(file.at("path")), text(file.at("text"))};
      if (sha256_hex(src.text) != file.at("sha256").get<std::string>()) {
        throw InputError(pos, printable_text(src.path) + ": its text does not match its SHA-256");
      }
      s.sources.push_back(std::move(src));
    }
    if (s.sources.empty()) throw InputError(pos, "settings without a mapping");
    if (s.rate_millihertz < kSlowestRate || s.rate_millihertz > kFastestRate) {
      throw InputError(pos, "a rate of " + std::to_string(s.rate_millihertz) + " millihertz: not one run sends at");
    }
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(pos, std::string("bad settings: ") + e.what());
  }
}

link::SendResult parse_result(std::string_view w, bool& offered, const SourcePos& pos) {
  offered = w != "none";
  if (w == "sent" || w == "none") return link::SendResult::kSent;
  if (w == "busy") return link::SendResult::kBusy;
  if (w == "down") return link::SendResult::kDown;
  throw InputError(pos, "unknown frame result " + quote(w));
}

void read_record(std::string_view kind, Fields& f, Session& s, std::optional<SessionSettings>& pending) {
  const auto& pos = f.pos();
  if (kind == kSessionMagic) {
    const auto format = f.integer();
    if (format < kOldestSessionFormat || format > kSessionFormat) {
      throw InputError(pos, "a session format this program does not read");
    }
    s.format = static_cast<int>(format);
  } else if (kind == "program") {
    f.word();
    s.version = std::string(f.word());
  } else if (kind == "started") {
    s.started = std::string(f.word());
    f.word();
    s.pid = static_cast<long>(f.integer());
    f.word();
    s.host = s.format >= kEscapedTextFormat ? unescape_text(f.rest(), pos) : std::string(f.rest());
  } else if (kind == "settings") {
    auto settings = parse_settings(f, f.json(), s.format);
    if (s.settings.sources.empty()) s.settings = settings;
    else pending = std::move(settings);
  } else if (kind == "event") {
    try {
      auto events = input::parse_event_script(std::string(f.rest()), pos.file);
      for (auto& e : events) s.events.push_back(std::move(e));
    } catch (const InputError& e) {
      throw InputError(pos, e.message());
    }
  } else if (kind == "request") {
    const auto t = time(f);
    const auto name = f.word();
    if (!parse_request(name)) throw InputError(pos, "unknown request " + quote(name));
    s.requests.push_back({t, std::string(name), pos.line});
  } else if (kind == "pause") {
    s.pauses.push_back(time(f));
  } else if (kind == "reload") {
    ReloadRecord r;
    r.t_ms = time(f);
    r.outcome.ok = f.word() == "ok";
    r.outcome.message = f.text(s.format);
    if (r.outcome.ok) {
      if (!pending) throw InputError(pos, "a reload without the settings it put in place");
      r.settings = std::exchange(pending, std::nullopt);
    }
    pending.reset();
    s.reloads.push_back(std::move(r));
  } else if (kind == "frame") {
    FrameRecord fr;
    fr.tick = f.integer();
    fr.t_ms = f.integer();
    fr.result = parse_result(f.word(), fr.offered, pos);
    fr.data = protocol::parse_data_hex(f.word());
    const auto gap = f.word();
    const auto g = gap.starts_with("gap=") ? to_integer(gap.substr(4)) : std::nullopt;
    if (!g || *g < 0) throw InputError(pos, "bad gap " + quote(gap));
    fr.gap = *g;
    fr.line = pos.line;
    if (!s.frames.empty() && fr.tick <= s.frames.back().tick) throw InputError(pos, "frame records out of order");
    check_tick(s, fr.tick, fr.t_ms, pos);
    if (fr.tick - fr.gap <= (s.frames.empty() ? -1 : s.frames.back().tick)) {
      throw InputError(pos, "gap=" + std::to_string(fr.gap) + " reaches back past the frame record before it");
    }
    s.frames.push_back(fr);
  } else if (kind == "state") {
    const auto t = time(f);
    const auto state = parse_op_state(f.rest());
    if (!state) throw InputError(pos, "unknown state " + quote(f.rest()));
    s.states.push_back({t, *state, pos.line});
  } else if (kind == "gate") {
    const auto t = time(f);
    s.gate_trips.push_back({t, f.text(s.format), pos.line});
  } else if (kind == "stop" || kind == "reset") {
    StopRecord r;
    r.t_ms = time(f);
    r.reset = kind == "reset";
    r.line = pos.line;
    const auto who = f.word();
    const auto by = parse_stopper(who);
    if (!by || (r.reset && *by == run::StopBy::kGate)) throw InputError(pos, "unknown stopper " + quote(who));
    r.by = *by;
    read_stop_pad(f, r);
    s.stops.push_back(std::move(r));
  } else if (kind == "layer") {
    const auto t = time(f);
    s.layers.push_back({t, f.text(s.format), pos.line});
  } else if (kind == "link") {
    LinkRecord l;
    l.t_ms = time(f);
    l.state = f.word() == "up" ? link::LinkState::kUp : link::LinkState::kConnecting;
    l.motion_allowed = f.word() == "motion";
    l.detail = f.text(s.format);
    s.links.push_back(std::move(l));
  } else if (kind == "input-end") {
    s.input_end = time(f);
  } else if (kind == "dropped") {
    const auto n = f.integer();
    if (n <= 0) throw InputError(pos, "a dropped record of no records");
    s.dropped += static_cast<std::uint64_t>(n);
    // Why, from format 3 (earlier ones wrote the count alone).
    if (!f.rest().empty()) s.dropped_why = f.text(s.format);
  } else if (kind == "end") {
    EndRecord e;
    e.t_ms = f.integer();
    f.word();
    e.last_tick = f.integer();
    f.word();
    e.frames_sent = static_cast<std::uint64_t>(f.integer());
    e.why = f.text(s.format);
    e.line = pos.line;
    // Its tick is where the last frame record leaves off, or later at the rate.
    if (e.last_tick != -1 || !s.frames.empty()) check_tick(s, e.last_tick, e.t_ms, pos);
    if (!s.frames.empty() && e.last_tick < s.frames.back().tick) {
      throw InputError(pos, "the end's tick " + std::to_string(e.last_tick) + " is before the last frame record's");
    }
    s.end = std::move(e);
  } else {
    throw InputError(pos, "unknown record " + quote(kind));
  }
}

/// One line's record into s.
void read_line(std::string_view line, const SourcePos& pos, Session& s, std::optional<SessionSettings>& pending) {
  std::string_view payload;
  std::string_view hash;
  if (!split_record(line, payload, hash)) throw InputError(pos, "not a session record");
  if (pos.line == 1 && !is_session_start(line)) throw InputError(pos, "not a session");
  Fields f(payload, pos);
  f.integer();  // SEQ: verify_session's
  const auto kind = f.word();
  try {
    read_record(kind, f, s, pending);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(pos, std::string("bad record: ") + e.what());
  } catch (const InputError& e) {
    if (!e.pos().file.empty()) throw;
    throw InputError(pos, e.message());  // a field's own check (a frame's data) names no place
  }
}

}  // namespace

Session read_session(const std::filesystem::path& path) {
  Session s;
  s.path = path.string();
  SessionLines lines(path);
  std::optional<SessionSettings> pending;
  while (const auto line = lines.next()) {
    const SourcePos pos{path.string(), lines.line_no()};
    try {
      read_line(*line, pos, s, pending);
    } catch (const InputError&) {
      // Half a record at the end: the run was cut off there; what is before it is read.
      if (pos.line == 1 || !lines.cut_short(*line)) throw;
      s.cut_short_line = pos.line;
      break;
    }
  }
  if (lines.line_no() == 0) throw InputError(SourcePos{path.string()}, "empty: not a session");
  if (s.settings.sources.empty()) throw InputError(SourcePos{path.string()}, "a session without its settings");
  check_record_spacing(s);
  return s;
}

}  // namespace andros::record
