#include "andros/run/session.hpp"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <utility>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "andros/input/events.hpp"

namespace andros::run {
namespace {

constexpr std::size_t kHashDigits = 64;
/// A session line longer than this is not one the recorder wrote (a mapping
/// file's text is the longest, bounded far below it by the loader).
constexpr std::size_t kMaxSessionLine = std::size_t{64} * 1024 * 1024;

std::string_view result_name(const FrameRecord& f) {
  if (!f.offered) return "none";
  switch (f.result) {
    case link::SendResult::kSent: return "sent";
    case link::SendResult::kBusy: return "busy";
    case link::SendResult::kDown: return "down";
  }
  return "?";
}

nlohmann::json settings_json(const SessionSettings& s) {
  nlohmann::json files = nlohmann::json::array();
  for (const auto& f : s.sources) files.push_back({{"path", f.path}, {"sha256", sha256_hex(f.text)}, {"text", f.text}});
  return {{"robot", s.robot},
          {"mapping", s.mapping_file},
          {"rate_millihertz", s.rate_millihertz},
          {"weapons", s.weapons},
          {"code", hex_byte(s.code)},
          {"center", s.center},
          {"port", s.port},
          {"baud", s.baud},
          {"input", s.input},
          {"config", s.config},
          {"supervised", s.supervised},
          {"files", files}};
}

/// Splits `PAYLOAD HASH` (HASH: 64 hex digits); false when the line is not one.
bool split_record(std::string_view line, std::string_view& payload, std::string_view& hash) {
  if (line.size() < kHashDigits + 2 || line[line.size() - kHashDigits - 1] != ' ') return false;
  payload = line.substr(0, line.size() - kHashDigits - 1);
  hash = line.substr(line.size() - kHashDigits);
  return std::all_of(hash.begin(), hash.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

/// The SEQ of a payload, or nullopt.
std::optional<std::uint64_t> seq_of(std::string_view payload) {
  const auto space = payload.find(' ');
  const auto value = to_integer(payload.substr(0, space));
  if (!value || *value < 0) return std::nullopt;
  return static_cast<std::uint64_t>(*value);
}

std::string chained_hash(const Sha256Digest& prev, std::string_view payload) {
  Sha256 sha;
  return to_hex(sha.update(prev).update(payload).finish());
}

Sha256Digest parse_digest(std::string_view hex) {
  Sha256Digest d{};
  for (std::size_t i = 0; i < d.size(); ++i) {
    d[i] = static_cast<std::uint8_t>(hex_value(hex[2 * i]) << 4 | hex_value(hex[2 * i + 1]));
  }
  return d;
}

/// Reads a session line by line, with line numbers.
class SessionLines {
 public:
  explicit SessionLines(const std::filesystem::path& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) throw RuntimeError(path.string() + ": cannot open for reading");
  }
  bool next(std::string& line) {
    if (!std::getline(in_, line)) {
      if (in_.bad()) throw RuntimeError(path_.string() + ": read error");
      return false;
    }
    ++line_no_;
    if (line.size() > kMaxSessionLine)
      throw InputError(SourcePos{path_.string(), line_no_}, "line too long for a session");
    return true;
  }
  [[nodiscard]] int line_no() const { return line_no_; }

 private:
  std::filesystem::path path_;
  std::ifstream in_;
  int line_no_ = 0;
};

/// The line of the record with this SEQ after line `after`, or 0.
int find_seq(const std::filesystem::path& path, std::uint64_t seq, int after) {
  SessionLines lines(path);
  std::string line;
  while (lines.next(line)) {
    std::string_view payload;
    std::string_view hash;
    if (lines.line_no() > after && split_record(line, payload, hash) && seq_of(payload) == seq) return lines.line_no();
  }
  return 0;
}

std::string records_text(std::uint64_t from, std::uint64_t to) {
  return from == to ? "record " + std::to_string(from) : "records " + std::to_string(from) + ".." + std::to_string(to);
}

}  // namespace

bool is_session_start(std::string_view first_line) {
  return first_line.starts_with("0 " + std::string(kSessionMagic) + " ");
}

std::string RecordChain::line(std::string_view payload) {
  std::string out = std::to_string(seq_++);
  out += ' ';
  out += payload;
  last_ = sha_.update(last_).update(out).finish();
  out += ' ';
  out += to_hex(last_);
  out += '\n';
  return out;
}

std::vector<MappingSource> read_mapping_sources(const std::vector<std::string>& chain) {
  std::vector<MappingSource> out;
  for (const auto& path : chain) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw InputError(SourcePos{path}, "cannot read the mapping again for the flight recorder");
    out.push_back({path, text.str()});
  }
  return out;
}

namespace record {

std::string header() { return std::string(kSessionMagic) + " " + std::to_string(kSessionFormat); }
std::string program(std::string_view version) { return "program andros-bridge " + std::string(version); }
std::string started(std::string_view local_time, long pid, std::string_view host) {
  return "started " + std::string(local_time) + " pid " + std::to_string(pid) + " host " + std::string(host);
}
std::string settings(const SessionSettings& s) { return "settings " + settings_json(s).dump(); }
std::string event(const input::InputEvent& e) { return "event " + input::format_event(e); }
std::string request(std::int64_t t_ms, Request r) {
  return "request " + std::to_string(t_ms) + " " + std::string(request_name(r));
}
std::string pause(std::int64_t t_ms) { return "pause " + std::to_string(t_ms); }
std::string reload(std::int64_t t_ms, const ReloadOutcome& o) {
  return "reload " + std::to_string(t_ms) + (o.ok ? " ok " : " failed ") + nlohmann::json(o.message).dump();
}
std::string frame(const TickReport& r, std::int64_t gap) {
  FrameRecord f{.offered = r.sent, .result = r.result};
  return "frame " + std::to_string(r.tick) + " " + std::to_string(r.t_ms) + " " + std::string(result_name(f)) + " " +
         protocol::to_hex(r.data) + " gap=" + std::to_string(gap);
}
std::string state(std::int64_t t_ms, OpState s) {
  return "state " + std::to_string(t_ms) + " " + std::string(to_string(s));
}
std::string stop(std::int64_t t_ms, StopBy by, std::string_view name) {
  return "stop " + std::to_string(t_ms) + (by == StopBy::kSupervisor ? " supervisor " : " operator ") +
         nlohmann::json(std::string(name)).dump();
}
std::string reset(std::int64_t t_ms, StopBy by) {
  return "reset " + std::to_string(t_ms) + (by == StopBy::kSupervisor ? " supervisor" : " operator");
}
std::string layer(std::int64_t t_ms, std::string_view layer) {
  return "layer " + std::to_string(t_ms) + " " + nlohmann::json(std::string(layer)).dump();
}
std::string link(std::int64_t t_ms, const link::LinkStatus& s) {
  return "link " + std::to_string(t_ms) + " " + std::string(link::to_string(s.state)) +
         (s.motion_allowed ? " motion " : " neutral-only ") + nlohmann::json(s.detail).dump();
}
std::string input_end(std::int64_t t_ms) { return "input-end " + std::to_string(t_ms); }
std::string dropped(std::uint64_t count) { return "dropped " + std::to_string(count); }
std::string end(std::int64_t t_ms, std::int64_t last_tick, std::uint64_t frames_sent, std::string_view why) {
  return "end " + std::to_string(t_ms) + " tick " + std::to_string(last_tick) + " frames " +
         std::to_string(frames_sent) + " " + nlohmann::json(std::string(why)).dump();
}

}  // namespace record

VerifyResult verify_session(const std::filesystem::path& path) {
  VerifyResult out;
  SessionLines lines(path);
  std::string line;
  Sha256Digest prev{};
  std::string prev_hash_text;
  const auto fail = [&](const std::string& what) {
    out.problem = what;
    return out;
  };
  while (lines.next(line)) {
    const int at = lines.line_no();
    const std::uint64_t want = out.records;
    std::string_view payload;
    std::string_view hash;
    if (!split_record(line, payload, hash) || !seq_of(payload)) {
      return fail("record " + std::to_string(want) + " (line " + std::to_string(at) + ") altered: not a record line");
    }
    if (want == 0 && !is_session_start(line))
      return fail("not a session: its first line is not '0 andros-session ...'");
    const std::uint64_t seq = *seq_of(payload);
    if (seq > want) {
      // Either the records before it were removed, or they come later: moved.
      if (const int later = find_seq(path, want, at); later != 0) {
        return fail("record " + std::to_string(want) + " reordered: found at line " + std::to_string(later) +
                    ", after record " + std::to_string(seq) + " (line " + std::to_string(at) + ")");
      }
      return fail(records_text(want, seq - 1) + " removed (before line " + std::to_string(at) + ")");
    }
    if (seq < want) {
      return fail("record " + std::to_string(seq) + " reordered: found at line " + std::to_string(at) +
                  ", after record " + std::to_string(want - 1));
    }
    if (chained_hash(prev, payload) != hash) {
      return fail("record " + std::to_string(want) + " (line " + std::to_string(at) +
                  ") altered: its content or hash no longer matches the chain");
    }
    prev = parse_digest(hash);
    prev_hash_text = std::string(hash);
    ++out.records;
    const auto kind_at = payload.find(' ');
    if (kind_at != std::string_view::npos && payload.substr(kind_at + 1).starts_with("end ")) out.closed = true;
    else out.closed = false;
  }
  if (out.records == 0) return fail("empty: not a session");
  out.intact = true;
  out.last_hash = prev_hash_text;
  return out;
}

namespace {

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

 private:
  std::string_view text_;
  SourcePos pos_;
};

SessionSettings parse_settings(const nlohmann::json& j, const SourcePos& pos) {
  try {
    SessionSettings s;
    s.robot = j.at("robot").get<std::string>();
    s.mapping_file = j.at("mapping").get<std::string>();
    // Format 1 wrote the same value as `rate_mhz`.
    s.rate_millihertz = j.at(j.contains("rate_millihertz") ? "rate_millihertz" : "rate_mhz").get<std::int64_t>();
    s.weapons = j.at("weapons").get<bool>();
    s.code = parse_code(j.at("code").get<std::string>(), pos);
    s.center = j.at("center").get<int>();
    s.port = j.at("port").get<std::string>();
    s.baud = j.at("baud").get<int>();
    s.input = j.at("input").get<std::string>();
    s.config = j.at("config").get<std::string>();
    s.supervised = j.value("supervised", false);
    for (const auto& f : j.at("files")) {
      MappingSource src{f.at("path").get<std::string>(), f.at("text").get<std::string>()};
      if (sha256_hex(src.text) != f.at("sha256").get<std::string>()) {
        throw InputError(pos, src.path + ": its text does not match its SHA-256");
      }
      s.sources.push_back(std::move(src));
    }
    if (s.rate_millihertz <= 0 || s.sources.empty()) throw InputError(pos, "settings without a rate or a mapping");
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
  } else if (kind == "program") {
    f.word();
    s.version = std::string(f.word());
  } else if (kind == "started") {
    s.started = std::string(f.word());
    f.word();
    s.pid = static_cast<long>(f.integer());
    f.word();
    s.host = std::string(f.rest());
  } else if (kind == "settings") {
    auto settings = parse_settings(f.json(), pos);
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
    const auto t = f.integer();
    const auto name = f.word();
    if (!parse_request(name)) throw InputError(pos, "unknown request " + quote(name));
    s.requests.push_back({t, std::string(name)});
  } else if (kind == "pause") {
    s.pauses.push_back(f.integer());
  } else if (kind == "reload") {
    ReloadRecord r;
    r.t_ms = f.integer();
    r.outcome.ok = f.word() == "ok";
    r.outcome.message = f.json().get<std::string>();
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
    if (!s.frames.empty() && fr.tick <= s.frames.back().tick) throw InputError(pos, "frame records out of order");
    s.frames.push_back(fr);
  } else if (kind == "state") {
    const auto t = f.integer();
    const auto state = parse_op_state(f.rest());
    if (!state) throw InputError(pos, "unknown state " + quote(f.rest()));
    s.states.push_back({t, *state});
  } else if (kind == "stop" || kind == "reset") {
    StopRecord r;
    r.t_ms = f.integer();
    r.reset = kind == "reset";
    const auto who = f.word();
    if (who != "operator" && who != "supervisor") throw InputError(pos, "unknown stopper " + quote(who));
    r.by = who == "supervisor" ? StopBy::kSupervisor : StopBy::kOperator;
    if (!r.reset) r.name = f.json().get<std::string>();
    s.stops.push_back(std::move(r));
  } else if (kind == "layer") {
    const auto t = f.integer();
    s.layers.push_back({t, f.json().get<std::string>()});
  } else if (kind == "link") {
    LinkRecord l;
    l.t_ms = f.integer();
    l.state = f.word() == "up" ? link::LinkState::kUp : link::LinkState::kConnecting;
    l.motion_allowed = f.word() == "motion";
    l.detail = f.json().get<std::string>();
    s.links.push_back(std::move(l));
  } else if (kind == "input-end") {
    s.input_end = f.integer();
  } else if (kind == "dropped") {
    s.dropped += static_cast<std::uint64_t>(f.integer());
  } else if (kind == "end") {
    EndRecord e;
    e.t_ms = f.integer();
    f.word();
    e.last_tick = f.integer();
    f.word();
    e.frames_sent = static_cast<std::uint64_t>(f.integer());
    e.why = f.json().get<std::string>();
    s.end = std::move(e);
  } else {
    throw InputError(pos, "unknown record " + quote(kind));
  }
}

}  // namespace

Session read_session(const std::filesystem::path& path) {
  Session s;
  s.path = path.string();
  SessionLines lines(path);
  std::string line;
  std::optional<SessionSettings> pending;
  while (lines.next(line)) {
    const SourcePos pos{path.string(), lines.line_no()};
    std::string_view payload;
    std::string_view hash;
    if (!split_record(line, payload, hash)) throw InputError(pos, "not a session record");
    if (lines.line_no() == 1 && !is_session_start(line)) throw InputError(pos, "not a session");
    Fields f(payload, pos);
    f.integer();  // SEQ: verify_session's
    const auto kind = f.word();
    try {
      read_record(kind, f, s, pending);
    } catch (const nlohmann::json::exception& e) {
      throw InputError(pos, std::string("bad record: ") + e.what());
    }
  }
  if (lines.line_no() == 0) throw InputError(SourcePos{path.string()}, "empty: not a session");
  if (s.settings.sources.empty()) throw InputError(SourcePos{path.string()}, "a session without its settings");
  return s;
}

const FrameRecord* Session::frame_at(std::int64_t tick) const {
  const auto it = std::upper_bound(frames.begin(), frames.end(), tick,
                                   [](std::int64_t t, const FrameRecord& f) { return t < f.tick; });
  return it == frames.begin() ? nullptr : &*std::prev(it);
}

std::int64_t Session::live_ticks() const {
  if (frames.empty()) return 0;
  const std::int64_t last = end ? end->last_tick : frames.back().tick;
  std::int64_t gaps = 0;
  for (const auto& f : frames) gaps += f.gap;
  return last + 1 - gaps;
}

std::int64_t Session::length_ms() const {
  if (end) return end->t_ms;
  return frames.empty() ? 0 : frames.back().t_ms;
}

std::string_view request_name(Request r) {
  switch (r) {
    case Request::kNone: return "none";
    case Request::kStop: return "stop";
    case Request::kSuspend: return "suspend";
    case Request::kResumed: return "resumed";
    case Request::kReload: return "reload";
  }
  return "?";
}

std::optional<Request> parse_request(std::string_view name) {
  for (const auto r : {Request::kStop, Request::kSuspend, Request::kResumed, Request::kReload}) {
    if (request_name(r) == name) return r;
  }
  return std::nullopt;
}

std::optional<OpState> parse_op_state(std::string_view name) {
  for (int i = 0; i <= static_cast<int>(OpState::kStopping); ++i) {
    const auto s = static_cast<OpState>(i);
    if (to_string(s) == name) return s;
  }
  return std::nullopt;
}

}  // namespace andros::run
