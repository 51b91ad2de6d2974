#include "andros/record/session_replay.hpp"

#include <optional>

#include "andros/base/error.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/record/recorded_loop.hpp"
#include "andros/record/recorder.hpp"
#include "andros/run/loop.hpp"
#include "record_check.hpp"

namespace andros::record {
namespace {

/// The session as the loop's world: its clock, input, link and controls,
/// with where the replay is now.
class Playback {
 public:
  Playback(const Session& s, const SourcesLoader& load) : s_(s), load_(load), schedule_(s.settings.rate_millihertz) {
    last_tick_ = s.end ? s.end->last_tick : (s.frames.empty() ? 0 : s.frames.back().tick);
  }

  Clock& clock() { return clock_; }
  [[nodiscard]] std::int64_t expected_tick() const { return expected_tick_; }
  [[nodiscard]] std::int64_t last_tick() const { return last_tick_; }

  // The input.
  void pump(input::TickInput& input, std::int64_t now_ms) {
    now_ms_ = now_ms;
    while (next_event_ < s_.events.size() && s_.events[next_event_].t_ms <= now_ms)
      input.apply(s_.events[next_event_++]);
  }
  [[nodiscard]] bool finished(std::int64_t now_ms) const { return s_.input_end && now_ms >= *s_.input_end; }

  // The link, as the live one answered.
  link::SendResult send() {
    link_ = status_at(now_ms_);
    const FrameRecord* f = s_.frame_at(expected_tick_);
    return f == nullptr ? link::SendResult::kDown : f->result;
  }
  void close_link() {
    link_.state = link::LinkState::kConnecting;
    link_.detail = link::kClosedDetail;
  }
  [[nodiscard]] const LinkRecord& link() const { return link_; }
  void start() { link_ = status_at(-1); }

  // The controls.
  /// Past the live run's last tick: a session cut short (or astray) ends here.
  [[nodiscard]] bool past_end() const { return expected_tick_ > last_tick_; }
  /// The request recorded at this tick's time, or none.
  run::Request poll() {
    if (next_request_ < s_.requests.size() && s_.requests[next_request_].t_ms == now_ms_) {
      return *parse_request(s_.requests[next_request_++].text);
    }
    return run::Request::kNone;
  }
  void pause() {
    // The live process was stopped until the pause's pump: the clock goes
    // there (its ms, and a time at which the same next tick is due).
    if (next_pause_ >= s_.pauses.size()) return;
    const std::int64_t resumed_ms = s_.pauses[next_pause_++];
    const std::int64_t next = jump_after(last_run_).value_or(last_run_ + 1);
    move_clock_to(std::max(resumed_ms * kNsPerMs, ns_due(next - 1)));
    expected_tick_ = next;
  }
  std::optional<run::ReloadOutcome> finish_reload() {
    if (next_reload_ >= s_.reloads.size() || s_.reloads[next_reload_].t_ms != now_ms_) return std::nullopt;
    const ReloadRecord& r = s_.reloads[next_reload_++];
    run::ReloadOutcome outcome = r.outcome;
    if (outcome.ok && r.settings) {
      outcome.frames = engine_frames(*r.settings);
      outcome.weapons = r.settings->weapons;  // the frame gate's rule, from the settings put in place
    }
    return outcome;
  }

  /// After tick's report: where the live loop went next (a stall skipped ticks).
  void ticked(std::int64_t tick) {
    last_run_ = tick;
    const auto jump = jump_after(tick);
    expected_tick_ = jump.value_or(tick + 1);
    if (!jump) return;
    const bool paused = next_pause_ < s_.pauses.size() && s_.pauses[next_pause_] <= schedule_.tick_ms(*jump);
    if (!paused) move_clock_to(ns_due(*jump));  // pause() moves it for a pause
  }

  std::shared_ptr<mapping::Engine> engine_frames(const SessionSettings& settings) {
    return std::make_shared<mapping::Engine>(
        load_(settings.sources), mapping::EngineOptions{.weapons = settings.weapons, .code = settings.code});
  }

 private:
  /// The tick the live loop ran after `tick`, when it was not tick + 1.
  [[nodiscard]] std::optional<std::int64_t> jump_after(std::int64_t tick) const {
    const FrameRecord* at = s_.frame_at(tick);
    const auto it = at == nullptr ? s_.frames.begin() : s_.frames.begin() + (at - s_.frames.data()) + 1;
    if (it == s_.frames.end() || it->gap == 0 || it->tick - it->gap - 1 != tick) return std::nullopt;
    return it->tick;
  }
  /// The first time at which tick is due.
  [[nodiscard]] std::int64_t ns_due(std::int64_t tick) const {
    std::int64_t e = schedule_.tick_ns(tick);
    while (schedule_.next_tick(-1, e) < tick) ++e;
    return e;
  }
  void move_clock_to(std::int64_t ns) {
    if (ns > clock_.now().count()) clock_.advance(Nanos(ns) - clock_.now());
  }
  /// The link as the last record at or before t_ms left it. t_ms never goes
  /// back (the pumps' times), so each record is passed once: a link that
  /// flapped every second costs a step per flap, not a walk from the start.
  [[nodiscard]] const LinkRecord& status_at(std::int64_t t_ms) {
    while (next_link_ < s_.links.size() && s_.links[next_link_].t_ms <= t_ms) status_ = s_.links[next_link_++];
    return status_;
  }

  const Session& s_;
  const SourcesLoader& load_;
  timing::TickSchedule schedule_;
  VirtualClock clock_;
  std::int64_t now_ms_ = -1;
  std::int64_t expected_tick_ = 0;
  std::int64_t last_run_ = -1;  ///< the last tick the replay ran
  std::int64_t last_tick_ = 0;  ///< the live run's last
  std::size_t next_event_ = 0;
  std::size_t next_request_ = 0;
  std::size_t next_pause_ = 0;
  std::size_t next_reload_ = 0;
  std::size_t next_link_ = 0;
  LinkRecord status_{-1, link::LinkState::kUp, true, ""};  ///< before the first link record
  LinkRecord link_;
};

class PlaybackInput final : public input::InputSource {
 public:
  PlaybackInput(Playback& p, bool supervised) : p_(p), supervised_(supervised) {}
  void pump(input::TickInput& input, std::int64_t now_ms) override { p_.pump(input, now_ms); }
  [[nodiscard]] bool finished(std::int64_t now_ms) const override { return p_.finished(now_ms); }
  [[nodiscard]] bool supervised() const override { return supervised_; }

 private:
  Playback& p_;
  bool supervised_;
};

class PlaybackLink final : public link::Link {
 public:
  explicit PlaybackLink(Playback& p) : p_(p) {}
  link::SendResult send(const protocol::Frame& /*frame*/, std::int64_t /*now_ns*/) override {
    const auto result = p_.send();
    switch (result) {
      case link::SendResult::kSent: ++counters_.sent; break;
      case link::SendResult::kBusy: ++counters_.busy; break;
      case link::SendResult::kDown: ++counters_.down; break;
    }
    return result;
  }
  bool drain_and_close(int /*timeout_ms*/) override {
    p_.close_link();
    return true;
  }
  [[nodiscard]] link::LinkState state() const override { return p_.link().state; }
  [[nodiscard]] const std::string& name() const override { return name_; }
  [[nodiscard]] const std::string& detail() const override { return p_.link().detail; }
  [[nodiscard]] const link::LinkCounters& counters() const override { return counters_; }
  [[nodiscard]] bool far_end_reading() const override { return p_.link().far_end_reading; }

 private:
  Playback& p_;
  std::string name_ = "recorded link";
  link::LinkCounters counters_;
};

std::string frame_text(const protocol::DataBytes& data) { return protocol::to_hex(data); }

}  // namespace

mapping::ValidMapping load_recorded_mapping(const std::vector<MappingSource>& sources) {
  if (sources.empty()) throw InputError("the session names no mapping file");
  std::vector<mapping::MappingText> files;
  files.reserve(sources.size());
  for (const auto& src : sources) files.push_back({src.path, src.text});
  return mapping::load_recorded_chain(files);
}

std::vector<mapping::ValidMapping> recorded_mappings(const Session& session, const SourcesLoader& load) {
  std::vector<mapping::ValidMapping> out;
  out.push_back(load(session.settings.sources));
  for (const auto& r : session.reloads) {
    if (r.settings) out.push_back(load(r.settings->sources));
  }
  return out;
}

SessionReplayResult replay_session(const Session& s, const SourcesLoader& load, const run::Bridge::Observer& observe) {
  if (s.dropped != 0) {
    throw InputError(SourcePos{s.path}, std::to_string(s.dropped) +
                                            " records were dropped while it was recorded (the queue or the disk "
                                            "was full): it cannot be replayed exactly");
  }
  SessionReplayResult out;
  // The records the loop writes, made again by the recorder the run uses, and compared as they come.
  RecordCheck check(s);
  Recorder recorder([&check](const std::string& payload) { check.made(payload); }, s.format);
  Playback playback(s, load);
  const auto engine = playback.engine_frames(s.settings);
  playback.start();
  PlaybackInput playback_input(playback, s.settings.supervised);
  RecordingInput input(playback_input, recorder);  // the request records' time is the pump's
  PlaybackLink link(playback);
  run::LoopParts loop{.clock = playback.clock(),
                      .input = input,
                      .frames = *engine,
                      .link = link,
                      .options = {.rate_millihertz = s.settings.rate_millihertz,
                                  .neutral_tail_at_end = true,
                                  .rules = {s.settings.weapons, s.settings.code}},
                      .control = {},
                      .observers = {}};
  loop.control.poll = [&] {
    if (playback.past_end()) return run::Request::kShutdown;
    const run::Request r = playback.poll();
    recorder.request(r);
    return r;
  };
  loop.control.pause = [&](const run::ShutdownReport&) { playback.pause(); };
  loop.control.begin_reload = [](const std::string&) {};  // its outcome is the session's
  loop.control.finish_reload = [&] { return playback.finish_reload(); };

  if (observe) loop.observers.push_back(observe);
  // Each tick's frame against the record in effect (a difference named at
  // its tick), then the tick's records against the session's.
  loop.observers.emplace_back([&](const run::TickReport& r) {
    ++out.ticks;
    if (r.tick != playback.expected_tick()) {
      check.differ("tick " + std::to_string(r.tick) + ": the live loop ran tick " +
                   std::to_string(playback.expected_tick()) + " here");
    } else if (r.tick <= playback.last_tick()) {
      const FrameRecord* live = s.frame_at(r.tick);
      const bool live_sent = live != nullptr && live->delivered();
      const std::string at = "tick " + std::to_string(r.tick) + " (" + std::to_string(r.t_ms) + " ms, line " +
                             std::to_string(live == nullptr ? 0 : live->line) + ")";
      if (live_sent && (!r.sent || r.data != live->data)) {
        check.differ(at + ": recorded " + frame_text(live->data) + ", replayed " +
                     (r.sent ? frame_text(r.data) : std::string("no frame")));
      } else if (live != nullptr && !live->offered && r.sent) {
        check.differ(at + ": the live loop sent nothing, the replay " + frame_text(r.data));
      }
      recorder.observe(r);
      if (live_sent && check.difference().empty()) ++out.compared;
    }
    playback.ticked(r.tick);
  });
  run::run_loop(loop);
  check.finish();
  if (s.end && out.compared != s.end->frames_sent) {
    check.differ("the live run sent " + std::to_string(s.end->frames_sent) + " frames, the replay reproduced " +
                 std::to_string(out.compared));
  }
  out.difference = check.difference();
  out.identical = out.difference.empty();
  out.records = check.matched();
  out.unproven = check.unproven();
  out.first_unproven_line = check.first_unproven_line();
  return out;
}

}  // namespace andros::record
