// read_checked_session (andros/record/session.hpp), the one reading of a
// session: the chain checked (session_verify.cpp) and the records turned back
// into what replay and plot need in the same pass, each checked as it is read
// against what a session can hold: its ticks fall at the recorded rate's
// times, within a day.
#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>

#include "andros/base/clock.hpp"
#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "andros/base/text_file.hpp"
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

/// ": they were dropped (WHY)" when the settings are missing and a `dropped`
/// record says why (a file-size limit under the settings' size); "" otherwise.
std::string settings_dropped(const Session& s) {
  return s.dropped_why.empty() ? std::string() : ": they were dropped (" + printable_text(s.dropped_why) + ")";
}

/// A tick and its time: the tick falls at that time at the session's rate, within kMaxSessionMs.
void check_tick(const Session& s, std::int64_t tick, std::int64_t t_ms, const SourcePos& pos) {
  if (s.settings.sources.empty()) throw InputError(pos, "a tick before the settings" + settings_dropped(s));
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

/// `end T tick K frames N "WHY"`, each field within what the session can
/// hold: K at T at the rate, at or after the last frame record's tick (-1,
/// at 0 ms: the run ended before its first tick), and at most K + 1 frames sent.
EndRecord read_end(Fields& f, const Session& s) {
  const auto& pos = f.pos();
  EndRecord e;
  e.t_ms = time(f);
  f.word();
  e.last_tick = f.integer();
  f.word();
  const auto frames = f.integer();
  e.why = f.text(s.format);
  e.line = pos.line;
  if (e.last_tick == -1 && s.frames.empty()) {
    if (e.t_ms != 0) throw InputError(pos, "an end before the first tick at " + std::to_string(e.t_ms) + " ms, not 0");
  } else {
    check_tick(s, e.last_tick, e.t_ms, pos);
    if (!s.frames.empty() && e.last_tick < s.frames.back().tick) {
      throw InputError(pos, "the end's tick " + std::to_string(e.last_tick) + " is before the last frame record's");
    }
  }
  // A frame at most each tick, 0 through the last.
  if (frames < 0 || frames > e.last_tick + 1) {
    throw InputError(pos, std::to_string(frames) + " frames sent: not within a session that ended at tick " +
                              std::to_string(e.last_tick) + " (at most " + std::to_string(e.last_tick + 1) + ")");
  }
  e.frames_sent = static_cast<std::uint64_t>(frames);
  return e;
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
  } else if (kind == "transition" && s.format >= kTransitionFormat) {
    const auto t = time(f);
    const auto transition = parse_transition(f.rest());
    if (!transition) throw InputError(pos, "unknown transition " + quote(f.rest()));
    s.transitions.push_back({t, *transition, pos.line});
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
    l.far_end_reading = f.word() == "motion";
    l.detail = f.text(s.format);
    s.links.push_back(std::move(l));
  } else if (kind == "input-end") {
    s.input_end = time(f);
  } else if (kind == "dropped") {
    const auto n = f.integer();
    if (n <= 0) throw InputError(pos, "a dropped record of no records");
    s.dropped += static_cast<std::uint64_t>(n);
    // Why (`dropped N "WHY"`, from format 3; earlier writers wrote the count alone).
    s.dropped_why = f.rest().empty() ? std::string() : f.text(s.format);
  } else if (kind == "end") {
    s.end = read_end(f, s);
  } else if (kind == "course") {
    // A trainer run's course, its text checked against its SHA-256 as a mapping's is.
    const auto j = f.json();
    CourseRecord c{f.text(j.at("name"), s.format), f.text(j.at("path"), s.format), f.text(j.at("text"), s.format),
                   pos.line};
    if (sha256_hex(c.text) != j.at("sha256").get<std::string>()) {
      throw InputError(pos, "the course's text does not match its SHA-256");
    }
    s.course = std::move(c);
  } else if (kind == "score") {
    const auto t = time(f);
    const auto j = f.json();
    if (!j.is_object()) throw InputError(pos, "a score must be a JSON object");
    s.score = ScoreRecord{t, j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), pos.line};
  } else {
    throw InputError(pos, "unknown record " + quote(kind));
  }
}

/// One line's record into s; true when it is a `dropped` record.
bool read_line(std::string_view line, const SourcePos& pos, Session& s, std::optional<SessionSettings>& pending) {
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
  return kind == "dropped";
}

/// The reasons a `dropped N "WHY"` gives for want of room, as the writer
/// (a write's strerror()) says them: the disk full (ENOSPC), a file-size
/// limit (EFBIG, `ulimit -f`), a disk quota (EDQUOT).
bool for_want_of_room(std::string_view why) {
  return why == std::strerror(ENOSPC) || why == std::strerror(EFBIG) || why == std::strerror(EDQUOT);
}

/// "a FIFO", "a directory"... when path is there and is not a regular file; "" otherwise.
std::string not_regular_kind(const std::filesystem::path& path) {
  const auto kind = path_kind(path.string());
  return kind.empty() || kind == "a regular file" ? std::string() : kind;
}

}  // namespace

void require_session_file(const std::filesystem::path& path) {
  if (const auto kind = not_regular_kind(path); !kind.empty()) {
    throw InputError(SourcePos{path.string()}, "is " + kind + ", not a session file");
  }
}

void RecordReader::read(std::string_view line, const SourcePos& pos) {
  const bool dropped = read_line(line, pos, s_, pending_);
  const bool room = dropped && for_want_of_room(s_.dropped_why);
  // Where recording stopped: the last frame record's tick before the first
  // `dropped` record for want of room (or before the last one, with no reason).
  const std::int64_t tick = s_.frames.empty() ? -1 : s_.frames.back().tick;
  if (room && !out_of_room_) room_tick_ = tick;
  out_of_room_ = out_of_room_ || room;
  // Records that end with a `dropped` one, for want of room or for no reason
  // given (an earlier writer's): the writer could write nothing after it.
  last_dropped_ = room || (dropped && s_.dropped_why.empty());
  if (last_dropped_ && !out_of_room_) room_tick_ = tick;
  if (keep_ == Keep::kVerdict) forget();
}

void RecordReader::forget() {
  // A frame record is checked against the one before it (its ticks' place,
  // and their spacing: the first error kept, for finish(), as a later
  // `dropped` record waives it); nothing else against an earlier record.
  if (s_.frames.size() > 1) {
    const auto& from = s_.frames[s_.frames.size() - 2];
    const auto& next = s_.frames.back();
    if (!spacing_) spacing_ = spacing_error(s_, from, next.tick - next.gap - 1, next.line);
    s_.frames.erase(s_.frames.begin(), s_.frames.end() - 1);
  }
  s_.events.clear();
  s_.requests.clear();
  s_.pauses.clear();
  s_.reloads.clear();
  s_.states.clear();
  s_.transitions.clear();
  s_.gate_trips.clear();
  s_.stops.clear();
  s_.layers.clear();
  s_.links.clear();
}

Session RecordReader::finish() && {
  if (s_.settings.sources.empty()) {
    throw InputError(SourcePos{s_.path}, "a session without its settings" + settings_dropped(s_));
  }
  if (keep_ == Keep::kVerdict && spacing_ && (s_.format >= kSpacedFormat && s_.dropped == 0)) throw *spacing_;
  check_record_spacing(s_, false, keep_ == Keep::kVerdict);
  // A `dropped` record for want of room says so whether the run closed or not
  // (the writer keeps room for its closing records); one with no reason, only
  // when the records end with it.
  if (out_of_room_ || (!s_.end && last_dropped_)) s_.stopped_for_room = room_tick_;
  return std::move(s_);
}

CheckedSession read_checked_session(const std::filesystem::path& path, Keep keep) {
  CheckedSession out;
  VerifyResult& v = out.verdict;
  SessionLines lines(path);
  ChainCheck chain(path);
  RecordReader records(path, keep);
  // The records are read while the chain holds and they read: after a
  // record that does not, the chain is still checked, for its verdict.
  const auto unreadable = [&out](InputError e) {
    if (!out.unreadable) out.unreadable = std::move(e);
  };
  while (true) {
    std::optional<std::string_view> line;
    try {
      line = lines.next();
    } catch (const InputError& e) {
      v.problem = "record " + std::to_string(chain.records()) + " (line " + std::to_string(e.pos().line) +
                  ") altered: " + e.message() + ", longer than any record";
      unreadable(e);
      break;
    }
    if (!line) break;
    const int at = lines.line_no();
    // NUL bytes to the end, after whole records: blocks a power loss left unwritten, not records.
    if (chain.records() != 0 && !line->empty() && line->find_first_not_of('\0') == std::string_view::npos) {
      if (const auto nul = lines.nul_tail(*line)) {
        v.nul_tail = *nul;
        break;
      }
      v.problem =
          "record " + std::to_string(chain.records()) + " (line " + std::to_string(at) + ") altered: not a record line";
      break;
    }
    // A line without its newline is never a whole record, whatever it holds: a write cut off.
    if (!lines.ended()) {
      if (chain.records() == 0) v.problem = "cut short at line 1: not one whole record, not a session";
      else v.cut_short_line = at;
      break;
    }
    if (auto problem = chain.take(*line, at); !problem.empty()) {
      v.problem = std::move(problem);
      if (chain.records() == 0) unreadable(InputError(SourcePos{path.string(), at}, "not a session"));
      break;
    }
    if (out.unreadable) continue;
    try {
      records.read(*line, SourcePos{path.string(), at});
    } catch (const InputError& e) {
      unreadable(e);
    }
  }
  v.records = chain.records();
  v.last_hash = chain.last_hash();
  v.closed = chain.closed() && v.cut_short_line == 0;
  if (v.records == 0 && v.problem.empty()) v.problem = "empty: not a session";
  v.intact = v.problem.empty();
  if (v.records == 0) unreadable(InputError(SourcePos{path.string()}, v.problem));
  if (out.unreadable) return out;
  try {
    out.session = std::move(records).finish();
    out.session->cut_short_line = v.cut_short_line;
  } catch (const InputError& e) {
    unreadable(e);
  }
  return out;
}

Session read_session(const std::filesystem::path& path) {
  auto checked = read_checked_session(path);
  if (checked.unreadable) throw *checked.unreadable;
  return std::move(*checked.session);
}

std::string closing_text(const CheckedSession& checked) {
  const auto& v = checked.verdict;
  if (v.closed) {
    std::string text = "closed: the run ended and its last record is here";
    // The writer keeps room for its last word: a full disk still closes the session.
    if (checked.session && checked.session->stopped_for_room) text += "; " + room_text(*checked.session);
    if (v.nul_tail != 0) {
      text += "; " + std::to_string(v.nul_tail) + " NUL bytes after it (blocks a power loss left unwritten)";
    }
    return text;
  }
  if (checked.session && checked.session->stopped_for_room) return "not closed: " + room_text(*checked.session);
  return "not closed: the run is still going, ended without closing it (a crash, power lost), or its last records "
         "were removed";
}

std::string room_text(const Session& s) {
  const auto tick = s.stopped_for_room.value_or(-1);
  return tick < 0 ? "recording stopped before the first tick: the disk was full or a file-size limit was reached"
                  : "recording stopped at tick " + std::to_string(tick) +
                        ": the disk was full or a file-size limit was reached";
}

}  // namespace andros::record
