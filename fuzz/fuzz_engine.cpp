// libFuzzer target: the engine driven by random controller input through
// every shipped mapping. On every frame the safety rules of docs/mapping.md
// are checked against this file's own reading of them, not the engine's:
// a valid frame with the code, no opposing pair both 1, nothing moving while
// not enabled, no weapon bit while weapons are off, and drive and pivot at
// centre after a change of meaning until their stick was seen at rest.
#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "andros/base/version.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/robots.hpp"
#include "fuzz_check.hpp"
#include "oracle/centre_watch.hpp"
#include "support/driven_engine.hpp"

namespace {

using namespace andros;

const std::vector<mapping::ValidMapping>& shipped() {
  static const auto mappings = [] {
    std::vector<mapping::ValidMapping> out;
    for (const auto robot : protocol::kRobotTypes) {
      out.push_back(
          mapping::load_mapping(mapping::find_robot_mapping(robot, {std::filesystem::path(kSourceMappingsDir)})));
    }
    return out;
  }();
  return mappings;
}

// The frame is neutral: every motion and weapon bit 0, drive and pivot at the protocol's 128.
bool is_neutral(const protocol::ControlState& s) {
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    const auto kind = protocol::kSignals[i].kind;
    if ((kind == protocol::SignalKind::kMotion || kind == protocol::SignalKind::kWeapon ||
         kind == protocol::SignalKind::kInterlock) &&
        s.values[i] != 0) {
      return false;
    }
    if (kind == protocol::SignalKind::kCentred && s.values[i] != protocol::kNeutralCentre) return false;
  }
  return true;
}

// Every 3 input bytes make one event: what, which input, value. Buttons and
// axes of a standard pad, connects and disconnects, and time moving on.
input::InputEvent next_event(const std::uint8_t* p, std::int64_t t) {
  input::InputEvent e;
  e.t_ms = t;
  switch (p[0] % 8) {
    case 0: e.type = input::InputEvent::Type::kConnect; break;
    case 1: e.type = input::InputEvent::Type::kDisconnect; break;
    case 2:
    case 3:
    case 4:
      e.type = input::InputEvent::Type::kButton;
      e.key = input::InputKey{input::InputKind::kPadButton,
                              static_cast<std::uint16_t>(p[1] % input::kPadButtonNames.size())};
      e.value = p[2] & 1;
      break;
    default:
      e.type = input::InputEvent::Type::kAxis;
      e.key =
          input::InputKey{input::InputKind::kPadAxis, static_cast<std::uint16_t>(p[1] % input::kPadAxisNames.size())};
      e.value = static_cast<int>(p[2] * 257) + input::kAxisMin;  // 0..255 over the whole axis
      break;
  }
  return e;
}

}  // namespace

using andros::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const auto& valid = shipped()[data[0] % shipped().size()];
  const mapping::Mapping& mapping = *valid;
  const bool weapons = (data[1] & 1) != 0;
  const std::uint8_t code = data[1];
  // The engine as the run loop drives it, up to its latch (held to the loop by tests/run/test_driven_engine.cpp).
  testing::DrivenEngine engine(valid, mapping::EngineOptions{weapons, code});
  const input::InputKey deadman = mapping.deadman->key;

  input::InputState input;
  bool fresh = false;  // the deadman went down after the last connect, not at it
  const std::array<protocol::SignalId, 2> centred{protocol::signal_id("drive"), protocol::signal_id("pivot")};
  std::array<test::CentreWatch, 2> centre{};
  bool was_enabled = false;
  int sessions = 0, seen_sessions = 0;
  std::int64_t t = 0, next_frame = 0;
  // The stop button (docs/mapping.md, "Stop"): a frame that sees it pressed
  // since the last one, or held, moves nothing (the run loop then latches it).
  bool stop_tapped = false;
  const auto stop_held = [&] { return mapping.estop && input.connected() && input.button(mapping.estop->key).down; };
  for (std::size_t i = 2; i + 3 <= size; i += 3) {
    t += data[i + 2] % 16;  // events land between frames, sometimes many per frame
    while (next_frame <= t) {
      const auto frame = engine.step(input, next_frame);
      const auto s = protocol::read_signals(frame);
      check(protocol::validation_errors(frame).empty());
      check(frame[protocol::kCodeByte] == code);
      for (std::size_t k = 0; k < protocol::kSignalCount; ++k) {
        const auto partner = protocol::partner_of(static_cast<protocol::SignalId>(k));
        check(!partner || s.values[k] == 0 || s[*partner] == 0);
        if (protocol::kSignals[k].kind == protocol::SignalKind::kWeapon && !weapons) check(s.values[k] == 0);
      }
      const bool stop = std::exchange(stop_tapped, false) || stop_held();
      const bool may_move = input.connected() && input.button(deadman).down && fresh && !stop;
      if (!may_move) check(is_neutral(s));
      for (std::size_t c = 0; c < centred.size(); ++c) {
        const mapping::Binding* now =
            may_move ? test::centre_driver(mapping, engine.status().layer, centred[c]) : nullptr;
        if (centre[c].must_centre(now, !was_enabled || sessions != seen_sessions,
                                  [&](input::InputKey key) { return input.axis(key); })) {
          check(s[centred[c]] == mapping.center);
        }
      }
      was_enabled = may_move;
      seen_sessions = sessions;
      check(s[protocol::signal_id("safety")] ==
            (engine.status().deadman == mapping::DeadmanState::kFreshHold && !stop ? 1 : 0));
      next_frame += 40;
    }
    const auto event = next_event(data + i, t);
    const bool was_down = input.button(deadman).down;
    const bool was_connected = input.connected();
    const auto stop_presses = mapping.estop ? input.button(mapping.estop->key).presses : 0U;
    input.apply(event);
    if (mapping.estop && input.button(mapping.estop->key).presses > stop_presses) stop_tapped = true;
    if (event.type == input::InputEvent::Type::kConnect) stop_tapped = false;  // gone with the old session
    if (event.type == input::InputEvent::Type::kConnect || !input.connected()) fresh = false;
    if (event.type == input::InputEvent::Type::kConnect) ++sessions;
    if (was_connected && input.connected() && !was_down && input.button(deadman).down &&
        input.button(deadman).presses > 0) {
      fresh = true;
    }
  }
  return 0;
}
