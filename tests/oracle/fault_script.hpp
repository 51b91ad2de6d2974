#pragma once
// Random event scripts with faults, for the fault simulation (the property
// test tests/run/test_fault_simulation.cpp and the fuzz target
// fuzz/fuzz_simulation.cpp, which drive the same generator with a seed or
// with the fuzzer's bytes). An operator on the standard pad (deadman LB,
// layers RB and the stick clicks, LT arming) driving, and around them what
// goes wrong: the controller lost and back, the link lost, taken and back
// (often within one frame), Ctrl-Z and fg, reloads of good, bad and missing
// mapping files, a stop; and the operator's stop button, squeezes of the
// trigger (a deadman on some mappings) past half way and all the way, and
// long pauses with nothing changing; and in some scripts a supervisor's
// controller, its stop tapped, lost and back; resets of a stop (a stop
// button released, then held about 2 s, by either pad, the deadman now and
// then pressed during it), and a deadman let go and pressed again, or the
// trigger squeezed past its panic point and back, within one frame. The deadman is often held through a fault, and
// often released and pressed again after one, and now and then a weapon is
// fired, so that both what must not move and what may move are reached.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "andros/input/events.hpp"

namespace andros::test {

/// The mapping files a script's `reload FILE` may name.
struct ReloadTargets {
  std::vector<std::string> good;  ///< files that load
  std::vector<std::string> bad;   ///< files that do not (missing, or failing to load)
};

template <typename Choices>
std::vector<input::InputEvent> fault_script(Choices& pick, const ReloadTargets& targets) {
  using T = input::InputEvent::Type;
  const auto button = [](std::string_view name) { return *input::parse_button_name(name); };
  const auto axis = [](std::string_view name) { return *input::parse_axis_name(name); };
  const input::InputKey deadman = button("leftshoulder");
  const std::array<input::InputKey, 3> layer_buttons = {button("rightshoulder"), button("leftstick"),
                                                        button("rightstick")};
  const input::InputKey arm = axis("lefttrigger");
  const input::InputKey drive = axis("lefty");
  const input::InputKey weapons_layer = button("leftstick");
  const input::InputKey fire_button = button("a");

  std::vector<input::InputEvent> events;
  std::int64_t t = 0;
  bool connected = true;
  bool held = false;  // the deadman, as the script last set it
  const auto add = [&](T type, input::InputKey key = {}, int value = 0, std::string name = {}) {
    input::InputEvent e;
    e.t_ms = t;
    e.type = type;
    e.key = key;
    e.value = value;
    e.name = std::move(name);
    events.push_back(std::move(e));
    if (type == T::kButton && key == deadman) held = value != 0;
    if (type == T::kConnect || type == T::kDisconnect) {
      connected = type == T::kConnect;
      held = false;
    }
  };
  // Time moves on: often not at all (events at one instant), to a frame's
  // time exactly, just past it, within a frame, or a long while.
  const auto wait = [&] {
    switch (pick.below(10)) {
      case 0:
      case 1:
      case 2: break;
      case 3: t = (t / 40 + 1) * 40; break;
      case 4: t += 1; break;
      case 9: t += 100 + pick.below(700); break;
      default: t += pick.below(60); break;
    }
  };
  // A second event of a pair (link down/up, suspend/resume): within the same
  // frame, within a stop's or suspend's neutral frames, or later.
  const auto pair_gap = [&] {
    switch (pick.below(4)) {
      case 0: t += pick.below(40); break;
      case 1: t += 40 + pick.below(100); break;
      default: t += 150 + pick.below(800); break;
    }
  };
  const auto rearm = [&] {     // the operator lets go of the deadman and presses it again, stick forward
    if (pick.below(3) == 0) {  // a trigger deadman (some mappings): released, squeezed to the middle
      add(T::kAxis, arm, 0);
      wait();
      add(T::kAxis, arm, 20000);
    } else {
      if (held) add(T::kButton, deadman, 0);
      wait();
      add(T::kButton, deadman, 1);
    }
    t += pick.below(50);
    add(T::kAxis, drive, pick.below(2) == 0 ? -32768 : 0);
  };
  const auto fire = [&] {  // into the weapons layer (a stick click), arm (LT), fire (A)
    add(T::kAxis, arm, 0);
    add(T::kButton, weapons_layer, 1);
    t += 1 + pick.below(40);
    add(T::kButton, weapons_layer, 0);
    t += pick.below(80);
    add(T::kAxis, arm, 32767);
    t += pick.below(80);
    add(T::kButton, fire_button, 1);
    t += pick.below(120);
    add(T::kButton, fire_button, 0);
  };

  const auto supervisor = [&](T type, input::InputKey key = {}, int value = 0) {
    add(type, key, value);
    events.back().pad = input::Pad::kSupervisor;
  };
  add(T::kConnect);
  if (pick.below(4) == 0) add(T::kButton, deadman, 1);  // held at connect: not a press
  const bool supervised = pick.below(4) == 0;           // a supervisor's controller, now and then
  if (supervised) supervisor(T::kConnect);
  const int n = 30 + static_cast<int>(pick.below(70));
  int after_stop = -1;  // events still to come once a stop is in
  for (int i = 0; i < n && after_stop != 0 && !pick.exhausted(); ++i) {
    if (after_stop > 0) --after_stop;
    wait();
    const auto roll = pick.below(100);
    if (roll < 3) {
      if (connected && pick.below(2) == 0) {
        add(T::kDisconnect);
      } else {
        add(T::kConnect);
        if (pick.below(3) == 0) add(T::kButton, deadman, 1);  // held at connect
      }
    } else if (roll < 22) {  // the deadman: held more often than not
      add(T::kButton, deadman, held ? static_cast<int>(pick.below(4) != 0) : 1);
    } else if (roll < 30) {
      add(T::kButton, layer_buttons[pick.below(layer_buttons.size())], static_cast<int>(pick.below(2)));
    } else if (roll < 36) {  // the weapons' arming trigger
      const std::array<int, 4> values = {0, 0, 20000, 32767};
      add(T::kAxis, arm, values[pick.below(values.size())]);
    } else if (roll < 56) {
      add(T::kButton, input::InputKey{input::InputKind::kPadButton, static_cast<std::uint16_t>(pick.below(15))},
          static_cast<int>(pick.below(2)));
    } else if (roll < 80) {  // rest (0) often: an input acts after a change of meaning only once seen at rest
      const std::array<int, 9> values = {-32768, -16384, -3000, 0, 0, 0, 3000, 16384, 32767};
      const int v =
          pick.below(2) == 0 ? values[pick.below(values.size())] : static_cast<int>(pick.below(65536)) - 32768;
      add(T::kAxis, input::InputKey{input::InputKind::kPadAxis, static_cast<std::uint16_t>(pick.below(6))}, v);
    } else {
      switch (pick.below(27)) {
        case 0:
        case 1:
        case 2:
        case 3:  // a flap: lost or taken, and back
          add(pick.below(3) == 0 ? T::kLinkTaken : T::kLinkDown);
          pair_gap();
          add(T::kLinkUp);
          break;
        case 4: add(T::kLinkUp); break;  // a stray one, or the end of a long outage
        case 5: add(pick.below(2) == 0 ? T::kLinkDown : T::kLinkTaken); break;
        case 6:
        case 7:
        case 8:  // Ctrl-Z, fg
          add(T::kSuspend);
          pair_gap();
          add(T::kResume);
          break;
        case 9: add(T::kSuspend); break;
        case 10: add(T::kResume); break;
        case 11: add(T::kReload); break;  // the same file again
        case 12:
        case 13:
          if (!targets.good.empty())
            add(T::kReload, {}, 0, targets.good[pick.below(static_cast<std::uint32_t>(targets.good.size()))]);
          break;
        case 14:
          if (!targets.bad.empty())
            add(T::kReload, {}, 0, targets.bad[pick.below(static_cast<std::uint32_t>(targets.bad.size()))]);
          break;
        case 15:
          add(T::kStop);
          after_stop = static_cast<int>(pick.below(4)) + 1;  // what follows a stop is never answered
          break;
        case 16: fire(); break;
        case 17:  // the stop button, tapped or held a while
          add(T::kButton, button("guide"), 1);
          t += pick.below(2) == 0 ? 0 : pick.below(300);
          add(T::kButton, button("guide"), 0);
          break;
        case 18:
        case 19: t += 900 + pick.below(1200); break;  // nothing changes for a while (an enable timeout)
        case 20:                                      // the supervisor's controller: its stop tapped, or lost and back
          if (!supervised) {
            rearm();
          } else if (pick.below(2) == 0) {
            supervisor(T::kButton, button("guide"), 1);
            t += pick.below(2) == 0 ? 0 : pick.below(300);
            supervisor(T::kButton, button("guide"), 0);
          } else {
            supervisor(T::kDisconnect);
            pair_gap();
            supervisor(T::kConnect);
          }
          break;
        case 21:
        case 22:
        case 23: {  // a reset: the stop button let go, then held about 2 s (the supervisor's, when there is one, now
                    // and then)
          const bool by_supervisor = supervised && pick.below(2) == 0;
          const auto press = [&](int value) {
            if (by_supervisor) supervisor(T::kButton, button("guide"), value);
            else add(T::kButton, button("guide"), value);
          };
          if (held && pick.below(4) != 0) add(T::kButton, deadman, 0);  // most often the deadman released first
          press(0);
          t += pick.below(100);
          press(1);
          const auto hold = pick.below(4) == 0 ? pick.below(2000) : 1950 + pick.below(300);
          if (pick.below(8) == 0) {  // the deadman pressed during the hold: no reset
            t += pick.below(static_cast<std::uint32_t>(hold) + 1);
            add(T::kButton, deadman, 1);
            t += 10;
            add(T::kButton, deadman, 0);
          } else {
            t += hold;
          }
          press(0);
          break;
        }
        case 24: {  // the deadman let go and pressed again within one frame
          t = (t / 40 + 1) * 40 + 1 + pick.below(10);
          add(T::kButton, deadman, 0);
          t += 1 + pick.below(25);
          add(T::kButton, deadman, 1);
          break;
        }
        case 25: {  // the trigger (a deadman on some mappings) squeezed past the panic point and back within one frame
          t = (t / 40 + 1) * 40 + 1 + pick.below(10);
          add(T::kAxis, arm, 32767);
          t += 1 + pick.below(25);
          add(T::kAxis, arm, pick.below(2) == 0 ? 20000 : 0);
          break;
        }
        default: rearm(); break;
      }
    }
  }
  t += pick.below(200);
  add(T::kEnd);
  return events;
}

}  // namespace andros::test
