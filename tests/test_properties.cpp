// Property test: random event scripts through every shipped mapping. Whatever
// the operator does, every frame passes validation, no opposing pair is both
// 1, nothing moves while not enabled, and weapons stay 0 without --weapons.
// `enabled` is checked against an independent reading of contract section 5.
#include <gtest/gtest.h>

#include <cstdint>
#include <sstream>

#include "andros/events.hpp"
#include "andros/mapping_loader.hpp"
#include "andros/replay.hpp"
#include "andros/robots.hpp"

namespace andros {
namespace {

constexpr int kScripts = 1000;

// A small generator of our own: the same numbers on every standard library.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed * 0x9E3779B97F4A7C15ULL + 1) {}
  std::uint32_t below(std::uint32_t n) {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 7;
    state_ ^= state_ << 17;
    return static_cast<std::uint32_t>(state_ % n);
  }

 private:
  std::uint64_t state_;
};

std::vector<InputEvent> random_script(Random& rng) {
  using T = InputEvent::Type;
  std::vector<InputEvent> events;
  std::int64_t t = 0;
  const auto add = [&](T type, InputKey key = {}, int value = 0) {
    InputEvent e;
    e.t_ms = t;
    e.type = type;
    e.key = key;
    e.value = value;
    events.push_back(e);
  };
  add(T::kConnect);
  const int n = 20 + static_cast<int>(rng.below(40));
  for (int i = 0; i < n; ++i) {
    t += rng.below(4) == 0 ? 0 : rng.below(60);
    const auto roll = rng.below(100);
    if (roll < 3) {
      add(rng.below(2) == 0 ? T::kDisconnect : T::kConnect);
    } else if (roll < 30) {  // the deadman and the layer buttons, often
      const std::array<std::string_view, 4> busy = {"leftshoulder", "rightshoulder", "leftstick", "rightstick"};
      add(T::kButton, *parse_button_name(busy[rng.below(busy.size())]), static_cast<int>(rng.below(2)));
    } else if (roll < 65) {
      add(T::kButton, InputKey{InputKind::kPadButton, static_cast<std::uint16_t>(rng.below(15))},
          static_cast<int>(rng.below(2)));
    } else {
      const std::array<int, 7> values = {-32768, -16384, -3000, 0, 3000, 16384, 32767};
      const int v = rng.below(2) == 0 ? values[rng.below(values.size())] : static_cast<int>(rng.below(65536)) - 32768;
      add(T::kAxis, InputKey{InputKind::kPadAxis, static_cast<std::uint16_t>(rng.below(6))}, v);
    }
  }
  t += 100;
  add(T::kEnd);
  return events;
}

// Contract section 5's `enabled`, read straight off the events: connected,
// deadman down, and pressed (0 -> 1) after the connect, not at its instant.
class EnabledOracle {
 public:
  explicit EnabledOracle(InputKey deadman) : deadman_(deadman) {}
  void apply(const InputEvent& e) {
    using T = InputEvent::Type;
    if (e.type == T::kConnect) {
      connected_ = true;
      connect_t_ = e.t_ms;
      down_ = fresh_ = false;
    } else if (e.type == T::kDisconnect) {
      connected_ = down_ = fresh_ = false;
    } else if (connected_ && e.type == T::kButton && e.key == deadman_) {
      if (e.value == 1 && !down_ && e.t_ms != connect_t_) fresh_ = true;
      down_ = e.value == 1;
    }
  }
  [[nodiscard]] bool enabled() const { return connected_ && down_ && fresh_; }

 private:
  InputKey deadman_;
  bool connected_ = false, down_ = false, fresh_ = false;
  std::int64_t connect_t_ = -1;
};

using Coverage = std::array<int, kSignalCount>;

void check_script(const Mapping& mapping, const std::vector<InputEvent>& script, bool weapons, Coverage& coverage) {
  std::string text;
  for (const auto& e : script) text += format_event(e) + "\n";
  TextReader in(text, "random.events", kEventScriptLimits);
  ScriptPlayer player(in);
  Engine engine(mapping, EngineOptions{weapons, 0x5A});
  EnabledOracle oracle(mapping.deadman->key);
  std::size_t next_event = 0;
  ControlState previous = read_signals(engine.neutral());
  replay(player, engine, FrameClock(kDefaultRateMillihertz), [&](std::int64_t t, const DataBytes& data) {
    while (next_event < script.size() && script[next_event].t_ms <= t) oracle.apply(script[next_event++]);
    const auto s = read_signals(data);
    const bool enabled = oracle.enabled();
    const auto where = [&] { return "t=" + std::to_string(t) + " in\n" + text; };
    ASSERT_TRUE(validation_errors(data).empty()) << where();
    ASSERT_EQ(data[kCodeByte], 0x5A);
    ASSERT_EQ(engine.status().enable == EnableState::kEnabled, enabled) << where();
    ASSERT_EQ(s[signal_id("safety")], enabled ? 1 : 0) << where();
    for (std::size_t i = 0; i < kSignalCount; ++i) {
      const auto id = static_cast<SignalId>(i);
      const auto& sig = kSignals[i];
      if (const auto p = partner_of(id)) {
        ASSERT_FALSE(s[id] && s[*p]) << sig.name << " with its partner, " << where();
      }
      if (sig.kind == SignalKind::kWeapon && (!weapons || !enabled)) {
        ASSERT_EQ(s[id], 0) << sig.name << ", " << where();
      }
      if (sig.is_bit() && s[id] != 0) ++coverage[id];
      if (enabled) continue;
      switch (sig.kind) {
        case SignalKind::kMotion:
        case SignalKind::kInterlock: ASSERT_EQ(s[id], 0) << sig.name << " while not enabled, " << where(); break;
        case SignalKind::kCentred: ASSERT_EQ(s[id], mapping.center) << sig.name << ", " << where(); break;
        case SignalKind::kLevel:
        case SignalKind::kSelector: ASSERT_EQ(s[id], previous[id]) << sig.name << " changed while not enabled, " << where(); break;
        default: break;
      }
    }
    previous = s;
  });
}

TEST(Properties, RandomScriptsThroughEveryShippedMapping) {
  std::vector<Mapping> mappings;
  for (const auto robot : kRobotTypes) {
    mappings.push_back(load_mapping(find_robot_mapping(robot, {ANDROS_MAPPINGS_DIR})));
  }
  Coverage coverage{};
  Random rng(20261122);
  for (int i = 0; i < kScripts; ++i) {
    const auto script = random_script(rng);
    for (const auto& m : mappings) {
      check_script(m, script, false, coverage);
      check_script(m, script, true, coverage);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  // The scripts do reach what the properties are about: motion and weapons.
  for (const auto name : {"drive_brake", "front_art_up", "pt_left", "shoulder_cw", "focus_up", "weapon_1", "laser"}) {
    EXPECT_GT(coverage[*find_signal(name)], 0) << name << " never sent";
  }
}

}  // namespace
}  // namespace andros
