#include "andros/record/session.hpp"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <utility>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "andros/input/events.hpp"

namespace andros::record {
namespace {

/// Text from outside as a JSON string: printable_text() of its bytes, which
/// is valid UTF-8 whatever they were (so the JSON layer cannot refuse it) and
/// gives them back whole (unescape_text()).
nlohmann::json text_json(std::string_view text) { return printable_text(text); }

nlohmann::json settings_json(const SessionSettings& s) {
  nlohmann::json files = nlohmann::json::array();
  for (const auto& f : s.sources) {
    files.push_back({{"path", text_json(f.path)}, {"sha256", sha256_hex(f.text)}, {"text", text_json(f.text)}});
  }
  return {{"robot", text_json(s.robot)},
          {"mapping", text_json(s.mapping_file)},
          {"rate_millihertz", s.rate_millihertz},
          {"weapons", s.weapons},
          {"code", hex_byte(s.code)},
          {"center", s.center},
          {"port", text_json(s.port)},
          {"baud", s.baud},
          {"input", text_json(s.input)},
          {"config", text_json(s.config)},
          {"supervised", s.supervised},
          {"files", files}};
}

}  // namespace

std::string_view result_name(const FrameRecord& f) {
  if (!f.offered) return "none";
  switch (f.result) {
    case link::SendResult::kSent: return "sent";
    case link::SendResult::kBusy: return "busy";
    case link::SendResult::kDown: return "down";
  }
  return "?";
}

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

std::string_view stopper_word(run::StopBy by) {
  switch (by) {
    case run::StopBy::kOperator: return "operator";
    case run::StopBy::kSupervisor: return "supervisor";
    case run::StopBy::kGate: return "gate";
  }
  return "?";
}

std::optional<run::StopBy> parse_stopper(std::string_view word) {
  for (const auto by : {run::StopBy::kOperator, run::StopBy::kSupervisor, run::StopBy::kGate}) {
    if (stopper_word(by) == word) return by;
  }
  return std::nullopt;
}

namespace {

/// A state's word as a transition record writes it: a space as `-` ("not-enabled").
std::string hyphened(std::string_view word) {
  std::string out(word);
  std::replace(out.begin(), out.end(), ' ', '-');
  return out;
}

}  // namespace

namespace payload {

std::string header() { return std::string(kSessionMagic) + " " + std::to_string(kSessionFormat); }
std::string program(std::string_view version) { return "program andros-bridge " + std::string(version); }
std::string started(std::string_view local_time, long pid, std::string_view host) {
  return "started " + std::string(local_time) + " pid " + std::to_string(pid) + " host " + printable_text(host);
}
std::string settings(const SessionSettings& s) { return "settings " + settings_json(s).dump(); }
std::string event(const input::InputEvent& e) { return "event " + input::format_event(e); }
std::string request(std::int64_t t_ms, run::Request r) {
  return "request " + std::to_string(t_ms) + " " + std::string(request_name(r));
}
std::string pause(std::int64_t t_ms) { return "pause " + std::to_string(t_ms); }
std::string reload(std::int64_t t_ms, const run::ReloadOutcome& o) {
  return "reload " + std::to_string(t_ms) + (o.ok ? " ok " : " failed ") + text_json(o.message).dump();
}
std::string frame(const FrameRecord& f) {
  return "frame " + std::to_string(f.tick) + " " + std::to_string(f.t_ms) + " " + std::string(result_name(f)) + " " +
         protocol::to_hex(f.data) + " gap=" + std::to_string(f.gap);
}
std::string frame(const run::TickReport& r, std::int64_t gap) {
  return frame(FrameRecord{
      .tick = r.tick, .t_ms = r.t_ms, .offered = r.sent, .result = r.result, .data = r.data, .gap = gap, .line = 0});
}
std::string course(const CourseRecord& c) {
  const nlohmann::json j{{"name", text_json(c.name)},
                         {"path", text_json(c.path)},
                         {"sha256", sha256_hex(c.text)},
                         {"text", text_json(c.text)}};
  return "course " + j.dump();
}
std::string score(std::int64_t t_ms, std::string_view json) {
  // Made again from the object: one line whatever was passed.
  return "score " + std::to_string(t_ms) + " " +
         nlohmann::json::parse(json).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}
std::string state(std::int64_t t_ms, run::OpState s) {
  return "state " + std::to_string(t_ms) + " " + std::string(state_word(s));
}
std::string transition(std::int64_t t_ms, const run::Transition& t) {
  return "transition " + std::to_string(t_ms) + " " + hyphened(state_word(t.from)) + " " +
         std::string(event_word(t.event)) + " " + hyphened(state_word(t.to)) + " " + std::string(who_word(t.who));
}
std::string gate(std::int64_t t_ms, std::string_view fault) {
  return "gate " + std::to_string(t_ms) + " " + text_json(fault).dump();
}
namespace {
std::string pad_json(const input::PadIdentity& pad, bool again = false) {
  nlohmann::json j{{"name", text_json(pad.name)},
                   {"path", text_json(pad.path)},
                   {"serial", text_json(pad.serial)},
                   {"guid", text_json(pad.guid)}};
  if (again) j["again"] = true;
  return j.dump();
}
}  // namespace
std::string stop(std::int64_t t_ms, run::StopBy by, const input::PadIdentity& pad, bool again) {
  return "stop " + std::to_string(t_ms) + " " + std::string(stopper_word(by)) + " " + pad_json(pad, again);
}
std::string reset(std::int64_t t_ms, run::StopBy by, const input::PadIdentity& pad) {
  return "reset " + std::to_string(t_ms) + " " + std::string(stopper_word(by)) + " " + pad_json(pad);
}
std::string layer(std::int64_t t_ms, std::string_view layer) {
  return "layer " + std::to_string(t_ms) + " " + text_json(layer).dump();
}
std::string link(std::int64_t t_ms, const link::LinkStatus& s) {
  return "link " + std::to_string(t_ms) + " " + std::string(link::to_string(s.state)) +
         (s.far_end_reading ? " motion " : " neutral-only ") + text_json(s.detail).dump();
}
std::string input_end(std::int64_t t_ms) { return "input-end " + std::to_string(t_ms); }
std::string dropped(std::uint64_t count, std::string_view why) {
  return "dropped " + std::to_string(count) + " " + text_json(why).dump();
}
std::string end(std::int64_t t_ms, std::int64_t last_tick, std::uint64_t frames_sent, std::string_view why) {
  return "end " + std::to_string(t_ms) + " tick " + std::to_string(last_tick) + " frames " +
         std::to_string(frames_sent) + " " + text_json(why).dump();
}

}  // namespace payload

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

std::uint64_t Session::frames_sent() const {
  if (end) return end->frames_sent;
  std::uint64_t sent = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto& f = frames[i];
    if (!f.offered || f.result != link::SendResult::kSent) continue;
    // Repeated on every tick to the next record's (less the ticks it skipped).
    const std::int64_t through = i + 1 < frames.size() ? frames[i + 1].tick - frames[i + 1].gap - 1 : f.tick;
    sent += static_cast<std::uint64_t>(through - f.tick + 1);
  }
  return sent;
}

std::int64_t Session::length_ms() const {
  if (end) return end->t_ms;
  return frames.empty() ? 0 : frames.back().t_ms;
}

std::string_view request_name(run::Request r) {
  switch (r) {
    case run::Request::kNone: return "none";
    case run::Request::kShutdown: return "stop";
    case run::Request::kSuspend: return "suspend";
    case run::Request::kResumed: return "resumed";
    case run::Request::kReload: return "reload";
  }
  return "?";
}

std::optional<run::Request> parse_request(std::string_view name) {
  for (const auto r :
       {run::Request::kShutdown, run::Request::kSuspend, run::Request::kResumed, run::Request::kReload}) {
    if (request_name(r) == name) return r;
  }
  return std::nullopt;
}

namespace {

/// The value of E (an enum counted from 0 to last) whose word is `word`.
template <class E, class Word>
std::optional<E> parse_word(std::string_view word, E last, Word word_of) {
  for (int i = 0; i <= static_cast<int>(last); ++i) {
    if (word_of(static_cast<E>(i)) == word) return static_cast<E>(i);
  }
  return std::nullopt;
}

}  // namespace

std::string_view state_word(run::OpState state) {
  using S = run::OpState;
  switch (state) {
    case S::kNoLink: return "no link";
    case S::kNoController: return "no controller";
    case S::kNotEnabled: return "not enabled";
    case S::kEnabled: return "enabled";
    case S::kStopped: return "stopped";
    case S::kSuspended: return "suspended";
    case S::kReloading: return "reloading";
    case S::kShuttingDown: return "stopping";  // the shutdown's word since the first format, whatever the screen says
  }
  return "?";
}

std::optional<run::OpState> parse_op_state(std::string_view name) {
  return parse_word(name, run::OpState::kShuttingDown, state_word);
}

std::string_view event_word(run::OpEvent event) {
  using E = run::OpEvent;
  switch (event) {
    case E::kLinkUp: return "link-up";
    case E::kLinkDown: return "link-down";
    case E::kLinkTaken: return "link-taken";
    case E::kControllerUp: return "controller-up";
    case E::kControllerDown: return "controller-down";
    case E::kFreshPress: return "deadman-fresh-press";
    case E::kRelease: return "deadman-released";
    case E::kPanic: return "deadman-panic";
    case E::kEnableTimeout: return "enable-timeout";
    case E::kOperatorStop: return "operator-stop";
    case E::kSupervisorStop: return "supervisor-stop";
    case E::kGateTrip: return "gate-trip";
    case E::kOperatorReset: return "operator-reset";
    case E::kSupervisorReset: return "supervisor-reset";
    case E::kReloadBegin: return "reload";
    case E::kReloadDone: return "reload-done";
    case E::kSuspend: return "suspend";
    case E::kResume: return "resume";
    case E::kShutdown: return "shutdown";
    case E::kNeutralSent: return "neutral-sent";
  }
  return "?";
}

std::string_view who_word(run::Who who) {
  using W = run::Who;
  switch (who) {
    case W::kOperator: return "operator";
    case W::kSupervisor: return "supervisor";
    case W::kGate: return "gate";
    case W::kLink: return "link";
    case W::kRequest: return "request";
    case W::kScript: return "script";
    case W::kTimeout: return "timeout";
    case W::kLoop: return "loop";
  }
  return "?";
}

std::optional<run::Transition> parse_transition(std::string_view fields) {
  std::vector<std::string_view> w;
  for (std::size_t at = 0; at <= fields.size() && w.size() < 5;) {
    const auto end = std::min(fields.find(' ', at), fields.size());
    w.push_back(fields.substr(at, end - at));
    at = end + 1;
  }
  if (w.size() != 4) return std::nullopt;
  const auto state = [](std::string_view word) {
    return parse_word(word, run::OpState::kShuttingDown, [](run::OpState s) { return hyphened(state_word(s)); });
  };
  const auto from = state(w[0]);
  const auto event = parse_word(w[1], run::OpEvent::kNeutralSent, event_word);
  const auto to = state(w[2]);
  const auto who = parse_word(w[3], run::Who::kLoop, who_word);
  if (!from || !event || !to || !who) return std::nullopt;
  return run::Transition{.from = *from, .event = *event, .to = *to, .who = *who};
}

}  // namespace andros::record
