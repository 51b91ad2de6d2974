// Property test: random event scripts through every shipped mapping. Whatever
// the operator does, every frame passes validation, no opposing pair is both
// 1, nothing moves while not enabled, weapons stay 0 without --weapons, and
// drive and pivot stay at centre after a change of meaning until their stick
// was seen at rest. `enabled` and the rest rule are checked against
// independent readings of docs/mapping.md's safety rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "andros/input/events.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/robots.hpp"
#include "andros/run/replay.hpp"
#include "oracle/centre_watch.hpp"
#include "oracle/random.hpp"
#include "support/sweep.hpp"

namespace andros::run {
namespace {

// Random scripts per property: 1,000, under the sanitizers too (250 never
// sent the laser there); the reuse check's quarter of them is a twentieth
// there (support/sweep.hpp).
constexpr int kScripts = 1000;

std::vector<input::InputEvent> random_script(test::Random& rng) {
  using T = input::InputEvent::Type;
  const auto deadman = *input::parse_button_name("leftshoulder");
  std::vector<input::InputEvent> events;
  std::int64_t t = 0;
  const auto add = [&](T type, input::InputKey key = {}, int value = 0) {
    input::InputEvent e;
    e.t_ms = t;
    e.type = type;
    e.key = key;
    e.value = value;
    events.push_back(e);
  };
  add(T::kConnect);
  const int n = 20 + static_cast<int>(rng.below(60));
  for (int i = 0; i < n; ++i) {
    t += rng.below(4) == 0 ? 0 : rng.below(60);
    const auto roll = rng.below(100);
    if (roll < 3) {
      add(rng.below(2) == 0 ? T::kDisconnect : T::kConnect);
    } else if (roll < 30) {  // the deadman and the layer buttons, often
      const std::array<std::string_view, 4> busy = {"leftshoulder", "rightshoulder", "leftstick", "rightstick"};
      const auto key = *input::parse_button_name(busy[rng.below(busy.size())]);
      // The deadman is held more often than not, so that sessions last long enough to do something.
      add(T::kButton, key, key == deadman ? static_cast<int>(rng.below(4) != 0) : static_cast<int>(rng.below(2)));
    } else if (roll == 30) {
      // A stop's reset: the shipped chord (back and start) held about 2 s; or the
      // stop button let go, then held about 2 s, which is a stop, never a reset.
      const bool chord = rng.below(3) != 0;
      const auto first = *input::parse_button_name(chord ? "back" : "guide");
      const auto second = *input::parse_button_name(chord ? "start" : "guide");
      add(T::kButton, first, 0);
      t += rng.below(60);
      add(T::kButton, first, 1);
      add(T::kButton, second, 1);
      t += 1900 + rng.below(300);
      add(T::kButton, first, 0);
      add(T::kButton, second, 0);
    } else if (roll == 31) {  // the deadman let go and pressed again between two frames
      add(T::kButton, deadman, 0);
      t += rng.below(30);
      add(T::kButton, deadman, 1);
    } else if (roll < 38) {  // the weapons' arming trigger (LT), squeezed or at rest
      add(T::kAxis, *input::parse_axis_name("lefttrigger"), rng.below(2) == 0 ? 0 : 32767);
    } else if (roll < 65) {
      add(T::kButton, input::InputKey{input::InputKind::kPadButton, static_cast<std::uint16_t>(rng.below(15))},
          static_cast<int>(rng.below(2)));
    } else {
      // Rest (0) often: an input that changed meaning acts again only once seen at rest.
      const std::array<int, 9> values = {-32768, -16384, -3000, 0, 0, 0, 3000, 16384, 32767};
      const int v = rng.below(2) == 0 ? values[rng.below(values.size())] : static_cast<int>(rng.below(65536)) - 32768;
      add(T::kAxis, input::InputKey{input::InputKind::kPadAxis, static_cast<std::uint16_t>(rng.below(6))}, v);
    }
  }
  t += 100;
  add(T::kEnd);
  return events;
}

// The safety rules' `enabled` (docs/mapping.md), read straight off the events: connected,
// deadman down, and pressed (0 -> 1) after the connect, not at its instant,
// and not let go since the last frame (every change between two frames
// counts); and not stopped: the stop button (docs/mapping.md, "Stop
// buttons") pressed or held latches at a frame, whatever came before (ISO
// 13850: a stop device stops whenever it is actuated); it is reset at a
// frame once the reset chord (`stop_reset`), made afresh while stopped (not
// held at the latch, nor at the first frame of a controller session), has
// been held for the hold (2 s) with the deadman and the stop button neither
// held nor pressed at any frame of it (either ends it: the chord is let go
// and made again); after the reset a press from then on is fresh.
class EnabledOracle {
 public:
  EnabledOracle(input::InputKey deadman, std::optional<input::InputKey> estop, std::vector<input::InputKey> reset,
                std::int64_t hold_ms)
      : deadman_(deadman), estop_(estop), reset_(std::move(reset)), hold_ms_(hold_ms) {}
  void apply(const input::InputEvent& e) {
    using T = input::InputEvent::Type;
    if (e.type == T::kConnect) {
      connected_ = true;
      connect_t_ = e.t_ms;
      // A new session: a stop tapped in the old one since the last frame went with it (docs/mapping.md, "Stop").
      down_ = fresh_ = stop_down_ = stop_pressed_ = deadman_pressed_ = let_go_ = false;
      chord_.clear();
      new_session_ = true;
    } else if (e.type == T::kDisconnect) {
      connected_ = down_ = fresh_ = stop_down_ = false;
      chord_.clear();
    } else if (connected_ && e.type == T::kButton && e.key == deadman_ && e.t_ms != connect_t_) {
      if (e.value == 1 && !down_) fresh_ = deadman_pressed_ = true;
      if (e.value == 0 && down_) let_go_ = true;
      down_ = e.value == 1;
    } else if (connected_ && e.type == T::kButton && e.key == deadman_) {
      down_ = e.value == 1;  // the state at connect: not a press
    } else if (connected_ && e.type == T::kButton && e.key == estop_) {
      const bool initial = e.t_ms == connect_t_;
      if (e.value == 1 && !stop_down_ && !initial) stop_pressed_ = true;
      stop_down_ = e.value == 1;
    } else if (connected_ && e.type == T::kButton && std::find(reset_.begin(), reset_.end(), e.key) != reset_.end()) {
      if (e.value == 0 && chord_.contains(e.key)) chord_let_go_ = true;
      if (e.value == 1) chord_.insert(e.key);
      if (e.value == 0) chord_.erase(e.key);
    }
  }
  /// At each frame t, after its events.
  void frame(std::int64_t t) {
    let_go_this_frame_ = let_go_;
    const bool made = !reset_.empty() && chord_.size() == reset_.size();
    const bool blocked = stop_pressed_ || stop_down_ || down_ || deadman_pressed_;
    if (!stopped_ && connected_ && (stop_pressed_ || stop_down_)) {
      stopped_ = true;
      open_ = !made;
      hold_since_.reset();
    } else if (!stopped_ || !connected_ || new_session_ || blocked) {
      open_ = !made;  // not read now: a chord held on is made again before it counts
      hold_since_.reset();
    } else {
      if (!made || chord_let_go_) {
        open_ = true;
        hold_since_.reset();
      }
      if (made && open_ && !hold_since_) hold_since_ = t;
      if (hold_since_ && t - *hold_since_ >= hold_ms_) {
        stopped_ = false;
        fresh_ = false;  // afresh: a press from now on
        open_ = false;
        hold_since_.reset();
        ++resets;
      }
    }
    stop_pressed_ = deadman_pressed_ = let_go_ = chord_let_go_ = new_session_ = false;
  }
  [[nodiscard]] bool enabled() const { return connected_ && down_ && fresh_ && !stopped_ && !let_go_this_frame_; }
  [[nodiscard]] bool stopped() const { return stopped_; }
  int resets = 0;

 private:
  input::InputKey deadman_;
  std::optional<input::InputKey> estop_;
  std::vector<input::InputKey> reset_;  ///< the reset chord
  std::int64_t hold_ms_;
  bool connected_ = false, down_ = false, fresh_ = false, deadman_pressed_ = false, let_go_ = false;
  bool let_go_this_frame_ = false;
  bool stop_down_ = false, stop_pressed_ = false, stopped_ = false;
  std::set<input::InputKey> chord_;  ///< its buttons held
  bool chord_let_go_ = false, open_ = false, new_session_ = false;
  std::optional<std::int64_t> hold_since_;
  std::int64_t connect_t_ = -1;
};

// The rest rule for drive and pivot, read off the mapping and the events: when
// the binding that drives one changes (a layer), or the bridge becomes enabled
// (also with a new pad between two frames), it stays at centre until its axis
// is seen inside that binding's deadzone at a frame.
class CentreOracle {
 public:
  explicit CentreOracle(const mapping::Mapping& mapping) : mapping_(mapping) {}

  void apply(const input::InputEvent& e) {
    using T = input::InputEvent::Type;
    if (e.type == T::kConnect || e.type == T::kDisconnect) {
      connected_ = e.type == T::kConnect;
      sessions_ += connected_ ? 1 : 0;
      axes_.clear();
    } else if (connected_ && e.type == T::kAxis) {
      axes_[e.key] = e.value;
    }
  }

  /// Once per frame: must `analog` be at centre now?
  bool must_centre(protocol::SignalId analog, const std::string& layer, bool enabled) {
    const mapping::Binding* now = enabled ? test::centre_driver(mapping_, layer, analog) : nullptr;
    return watch_[analog].must_centre(now, !enabled_ || sessions_ != seen_sessions_, [this](input::InputKey key) {
      const auto it = axes_.find(key);
      return it == axes_.end() ? 0 : it->second;
    });
  }

  void end_frame(bool enabled) {
    enabled_ = enabled;
    seen_sessions_ = sessions_;
  }

 private:
  const mapping::Mapping& mapping_;
  std::map<input::InputKey, int> axes_;
  std::map<protocol::SignalId, test::CentreWatch> watch_;
  bool connected_ = false;
  bool enabled_ = false;
  int sessions_ = 0;
  int seen_sessions_ = 0;
};

using Coverage = std::array<int, protocol::kSignalCount>;

int stops = 0;   ///< frames in "stopped", over all scripts
int resets = 0;  ///< stops reset, over all scripts

void check_script(const mapping::ValidMapping& valid, const std::vector<input::InputEvent>& script, bool weapons,
                  Coverage& coverage) {
  const mapping::Mapping& mapping = *valid;
  std::string text;
  for (const auto& e : script) text += input::format_event(e) + "\n";
  TextReader in(text, "random.events", kEventScriptLimits);
  input::ScriptPlayer player(in);
  mapping::Engine engine(valid, mapping::EngineOptions{weapons, 0x5A});
  std::vector<input::InputKey> reset;
  for (const auto& u : mapping.stop_reset) reset.push_back(u.key);
  EnabledOracle oracle(mapping.deadman->key,
                       mapping.estop ? std::optional<input::InputKey>(mapping.estop->key) : std::nullopt, reset,
                       mapping.stop_reset_hold_ms);
  CentreOracle centre(mapping);
  std::size_t next_event = 0;
  protocol::ControlState previous = protocol::read_signals(engine.neutral());
  TickReport last;  // the tick's report comes before its frame
  ReplayOptions options{.engine = {weapons, 0x5A}};
  options.observe = [&last](const TickReport& r) { last = r; };
  replay(player, std::move(engine), options, [&](std::int64_t t, const protocol::DataBytes& data) {
    for (; next_event < script.size() && script[next_event].t_ms <= t; ++next_event) {
      oracle.apply(script[next_event]);
      centre.apply(script[next_event]);
    }
    oracle.frame(t);
    const auto s = protocol::read_signals(data);
    const bool enabled = oracle.enabled();
    const auto where = [&] { return "t=" + std::to_string(t) + " in\n" + text; };
    ASSERT_TRUE(protocol::validation_errors(data).empty()) << where();
    ASSERT_EQ(data[protocol::kCodeByte], 0x5A);
    ASSERT_EQ(last.enabled(), enabled) << where();
    ASSERT_EQ(last.state == OpState::kStopped, oracle.stopped()) << where();
    ASSERT_EQ(s[protocol::signal_id("safety")], enabled ? 1 : 0) << where();
    for (const auto id : {protocol::signal_id("drive"), protocol::signal_id("pivot")}) {
      if (centre.must_centre(id, last.engine.layer, enabled)) {
        ASSERT_EQ(s[id], mapping.center) << protocol::info(id).name << " before its stick was seen at rest, "
                                         << where();
      } else if (enabled && s[id] != mapping.center) {
        ++coverage[id];
      }
    }
    centre.end_frame(enabled);
    stops += oracle.stopped() ? 1 : 0;
    resets += oracle.resets;
    oracle.resets = 0;
    for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
      const auto id = static_cast<protocol::SignalId>(i);
      const auto& sig = protocol::kSignals[i];
      if (const auto p = protocol::partner_of(id)) {
        ASSERT_FALSE(s[id] && s[*p]) << sig.name << " with its partner, " << where();
      }
      if (sig.kind == protocol::SignalKind::kWeapon && (!weapons || !enabled)) {
        ASSERT_EQ(s[id], 0) << sig.name << ", " << where();
      }
      if (sig.kind == protocol::SignalKind::kWeapon && s[id] != 0) {
        ASSERT_TRUE(last.engine.weapons_mode) << sig.name << " outside a weapons mode, " << where();
      }
      if (sig.is_bit() && s[id] != 0) ++coverage[id];
      if (enabled) continue;
      switch (sig.kind) {
        case protocol::SignalKind::kMotion:
        case protocol::SignalKind::kInterlock:
          ASSERT_EQ(s[id], 0) << sig.name << " while not enabled, " << where();
          break;
        case protocol::SignalKind::kCentred:
          ASSERT_EQ(s[id], protocol::kNeutralCentre) << sig.name << ", " << where();
          break;
        case protocol::SignalKind::kLevel:
        case protocol::SignalKind::kSelector:
          ASSERT_EQ(s[id], previous[id]) << sig.name << " changed while not enabled, " << where();
          break;
        default: break;
      }
    }
    previous = s;
  });
}

TEST(Properties, RandomScriptsThroughEveryShippedMapping) {
  std::vector<mapping::ValidMapping> mappings;
  for (const auto robot : protocol::kRobotTypes) {
    mappings.push_back(mapping::load_mapping(mapping::find_robot_mapping(robot, {ANDROS_MAPPINGS_DIR})));
  }
  Coverage coverage{};
  test::Random rng(20261122);
  // Under the sanitizers half: the same scripts' paths, the coverage below still reached (tests/support/sweep.hpp).
  const int scripts = test::sweep_size(kScripts, kScripts / 2);
  for (int i = 0; i < scripts; ++i) {
    const auto script = random_script(rng);
    for (const auto& m : mappings) {
      check_script(m, script, false, coverage);
      check_script(m, script, true, coverage);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  // The scripts do reach what the properties are about: motion and weapons.
  for (const auto name :
       {"drive_brake", "drive", "pivot", "front_art_up", "pt_left", "shoulder_cw", "focus_up", "weapon_1", "laser"}) {
    EXPECT_GT(coverage[*protocol::find_signal(name)], 0) << name << " never sent";
  }
  EXPECT_GT(stops, 0) << "no script pressed the stop button";
  EXPECT_GT(resets, 0) << "no script reset a stop";
}

/// What a replay did on each tick: its report's time, frame, state and engine status.
struct Tick {
  std::int64_t t_ms = 0;
  protocol::DataBytes data{};
  OpState state = OpState::kNoLink;
  mapping::EngineStatus engine;
  bool operator==(const Tick&) const = default;
};

std::vector<Tick> replay_ticks(const mapping::ValidMapping& valid, const std::string& text, bool weapons, bool reuse) {
  TextReader in(text, "random.events", kEventScriptLimits);
  input::ScriptPlayer player(in);
  const mapping::EngineOptions engine{.weapons = weapons, .code = 0x5A, .reuse_settled = reuse};
  std::vector<Tick> ticks;
  ReplayOptions options{.engine = engine};
  options.observe = [&ticks](const TickReport& r) { ticks.push_back({r.t_ms, r.data, r.state, r.engine}); };
  std::int64_t delivered = 0;
  replay(player, mapping::Engine(valid, engine), options,
         [&](std::int64_t, const protocol::DataBytes&) { ++delivered; });
  ticks.push_back({delivered, {}, OpState::kShuttingDown, {}});  // and how many frames reached the link
  return ticks;
}

// The engine gives a settled step's frame again rather than computing it
// (Engine::step). Every tick of a run, its frame, state and engine status,
// must be those of an engine that computes every step afresh.
TEST(Properties, ReusedStepsAreTheStepsComputedAfresh) {
  std::vector<mapping::ValidMapping> mappings;
  for (const auto robot : protocol::kRobotTypes) {
    mappings.push_back(mapping::load_mapping(mapping::find_robot_mapping(robot, {ANDROS_MAPPINGS_DIR})));
  }
  // The enable timeout, the panic point, the stop and the speed levels.
  mappings.push_back(mapping::load_mapping(std::string(ANDROS_TEST_DATA_DIR) + "/mappings/safety.yaml"));
  test::Random rng(20261123);
  int quiet = 0;  // ticks with no event since the one before last: there a step is reused
  const int scripts = test::sweep_size(kScripts / 4, kScripts / 40);
  for (int i = 0; i < scripts; ++i) {
    // Slowed down four times: the hands rest between events, as they mostly do.
    auto script = random_script(rng);
    for (auto& e : script) e.t_ms *= 4;
    std::string text;
    for (const auto& e : script) text += input::format_event(e) + "\n";
    for (std::int64_t t = 80, k = 0; t <= script.back().t_ms; t += 40) {
      while (k < static_cast<std::int64_t>(script.size()) && script[static_cast<std::size_t>(k)].t_ms <= t - 80) ++k;
      quiet += k == static_cast<std::int64_t>(script.size()) || script[static_cast<std::size_t>(k)].t_ms > t ? 1 : 0;
    }
    for (const auto& m : mappings) {
      for (const bool weapons : {false, true}) {
        const auto reused = replay_ticks(m, text, weapons, true);
        const auto computed = replay_ticks(m, text, weapons, false);
        ASSERT_EQ(reused.size(), computed.size()) << text;
        for (std::size_t k = 0; k < reused.size(); ++k) {
          ASSERT_EQ(reused[k], computed[k]) << "tick at t=" << computed[k].t_ms << " of\n" << text;
        }
      }
    }
  }
  EXPECT_GT(quiet, 4 * scripts);
}

}  // namespace
}  // namespace andros::run
