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
// long pauses with nothing changing; and in every other script a
// supervisor's controller, its stop tapped, lost and back. The deadman is
// often held through a fault, and often released and pressed again after
// one, and now and then a weapon is fired (armed or not), so that both what
// must not move and what may move are reached. And the moves the safety rules
// are about: the stop tapped within one tick and the deadman pressed within
// the next; the stop held through a release and press of the deadman; a
// trigger squeezed past its panic point and back to the middle; a layer left
// with its stick pushed; both buttons of an opposing pair; resets of a stop
// (the pad's reset chord, back and start, held about 2 s, by either pad, the
// deadman or a stop button now and then pressed during it); stops from both
// pads at once, pressed again and held (through a reset chord and a deadman
// press); a pad swapped for another (another name) while stopped; a
// deadman let go and pressed again, or the trigger squeezed past its panic
// point and back, within one frame; a toggled layer through a deadman
// release, its buttons pressed after; resets after stops held through a
// deadman press, the deadman now and then tapped before the gesture; and
// speed levels stepped up and down with a stick pushed.

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "andros/input/events.hpp"
#include "oracle/script_writer.hpp"

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
  const input::InputKey weapons_layer = button("rightshoulder");
  const input::InputKey fire_button = button("a");

  ScriptWriter<Choices> w(pick, deadman);
  auto& events = w.events;
  auto& t = w.t;
  const bool& connected = w.connected;
  const bool& held = w.held;
  bool& supervised = w.supervised;
  const auto add = [&w](T type, input::InputKey key = {}, int value = 0, std::string name = {}) {
    w.add(type, key, value, std::move(name));
  };
  const auto supervisor = [&w](T type, input::InputKey key = {}, int value = 0, std::string name = {}) {
    w.supervisor(type, key, value, std::move(name));
  };
  const auto wait = [&w] { w.wait(); };
  const auto pair_gap = [&w] { w.pair_gap(); };
  const auto next_tick = [&w](int within) { w.next_tick(within); };
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
  // The weapons layer held (RB), armed (LT) or not, fire (A); in a supervised
  // script the supervisor's consent (its A): given in the layer, let go after
  // or held on (held since before the next: no consent); given before the
  // layer is entered (no consent either, now and then let go and given again
  // once armed); or given only once the fire button is held (it waits until
  // pressed again), or not at all. Now and then the deadman (LB) pressed
  // first; and one time in three for the trigger deadmen (the even seeds'
  // mappings, whose weapons arm with RB and fire with A or B): LT let go and
  // squeezed to the middle afresh (enabled there, armed on the others) and
  // kept there, the fire button A or B.
  const auto fire = [&] {
    enum class Consent { kNone, kInLayer, kBefore, kLate };
    const auto consent = supervised ? static_cast<Consent>(pick.below(4)) : Consent::kNone;
    const bool trigger = pick.below(3) == 0;
    const input::InputKey fire_with = trigger && pick.below(2) == 0 ? button("b") : fire_button;
    if (!held && pick.below(2) == 0) add(T::kButton, deadman, 1);
    add(T::kAxis, arm, 0);
    if (consent == Consent::kBefore) {
      supervisor(T::kButton, fire_button, 1);
      t += 40 + pick.below(80);
    }
    if (trigger) {
      t += 40 + pick.below(40);  // seen released at a frame
      add(T::kAxis, arm, 20000);
      t += 40 + pick.below(80);
    }
    add(T::kButton, weapons_layer, 1);
    if (consent == Consent::kInLayer) {
      t += pick.below(60);
      supervisor(T::kButton, fire_button, 1);
    }
    const bool early = pick.below(3) == 0;  // fire held before arming: nothing until pressed again
    if (early) add(T::kButton, fire_with, 1);
    t += 1 + pick.below(80);
    if (!trigger) add(T::kAxis, arm, pick.below(3) == 0 ? 0 : 32767);
    t += pick.below(80);
    if (consent == Consent::kBefore && pick.below(2) == 0) {  // given afresh
      supervisor(T::kButton, fire_button, 0);
      t += 1 + pick.below(60);
      supervisor(T::kButton, fire_button, 1);
      t += 1 + pick.below(40);
    }
    if (early) {
      t += 40 + pick.below(80);
      add(T::kButton, fire_with, 0);
      t += pick.below(80);
    }
    add(T::kButton, fire_with, 1);
    if (consent == Consent::kLate) {
      t += 1 + pick.below(80);
      supervisor(T::kButton, fire_button, 1);
      t += 40 + pick.below(80);
      if (pick.below(2) == 0) {
        add(T::kButton, fire_with, 0);
        t += 1 + pick.below(60);
        add(T::kButton, fire_with, 1);
      }
    }
    t += pick.below(120);
    add(T::kButton, fire_with, 0);
    add(T::kButton, weapons_layer, 0);
    if (consent != Consent::kNone && pick.below(2) == 0) supervisor(T::kButton, fire_button, 0);
  };

  const auto stick = [&] {
    t += pick.below(50);
    add(T::kAxis, drive, pick.below(3) == 0 ? 0 : -32768);
  };
  // The deadman let go, the stop button tapped within one tick (now and then
  // with a resume in it, which answers the stop at once), the deadman pressed
  // again within the next: the stop must outlive its own tick.
  const auto stop_and_press = [&] {
    if (held) add(T::kButton, deadman, 0);
    const bool by_supervisor = supervised && pick.below(2) == 0;
    for (int taps = 1 + static_cast<int>(pick.below(3) == 0); taps > 0; --taps) {  // tapped again while stopped
      next_tick(20);
      add(T::kButton, button("guide"), 1);
      if (by_supervisor) events.back().pad = input::Pad::kSupervisor;
      t += 1 + pick.below(10);
      add(T::kButton, button("guide"), 0);
      if (by_supervisor) events.back().pad = input::Pad::kSupervisor;
    }
    if (pick.below(2) == 0) add(T::kResume);
    next_tick(38);
    add(T::kButton, deadman, 1);
    stick();
  };
  // The stop button held while the deadman is released and pressed again: never a reset.
  const auto stop_held_through_a_press = [&] {
    add(T::kButton, button("guide"), 1);
    t += 40 + pick.below(100);
    if (held) add(T::kButton, deadman, 0);
    t += 40 + pick.below(100);
    add(T::kButton, deadman, 1);
    stick();
    t += 40 + pick.below(200);
    if (pick.below(2) == 0) add(T::kButton, button("guide"), 0);
  };
  // A trigger deadman squeezed past its panic point and back to the middle,
  // not fully released: still off.
  const auto panic_and_back = [&] {
    add(T::kAxis, arm, 20000);
    wait();
    add(T::kAxis, arm, 32767);
    t += pick.below(100);
    add(T::kAxis, arm, 20000 + static_cast<int>(pick.below(5000)));
    stick();
  };
  // Into the arm layer (a toggle), a stick pushed, out again with it held: drive waits until it is back at rest.
  const auto leave_a_layer_stick_held = [&] {
    if (!held) add(T::kButton, deadman, 1);
    const input::InputKey toggle = layer_buttons[1 + pick.below(2)];
    for (const int v : {1, 0}) add(T::kButton, toggle, v);
    t += 40 + pick.below(80);
    add(T::kAxis, pick.below(2) == 0 ? drive : axis("leftx"), pick.below(2) == 0 ? -32768 : 30000);
    t += 40 + pick.below(80);
    for (const int v : {1, 0}) add(T::kButton, toggle, v);
    t += 40 + pick.below(160);
    if (pick.below(2) == 0) add(T::kAxis, drive, 0);
  };
  // A button on the operator's pad or the supervisor's.
  const auto on_pad = [&](bool sup, std::string_view name, int value) {
    if (sup) {
      supervisor(T::kButton, button(name), value);
    } else {
      add(T::kButton, button(name), value);
    }
  };
  // A reset: the pad's chord (back and start, now and then a moment apart)
  // held about 2 s (the supervisor's, when there is one, now and then); now
  // and then the deadman or a stop button (either pad's) pressed during it: no reset.
  // The oracle cannot tell at which tick a suspend asked for during a reload
  // begins (LoopSchedule::suspending), so not which ticks the loop spends
  // stopped, where a reset gesture is read: a gesture is made neither while
  // suspended (it is resumed first) nor within a second of a reload, a suspend or a resume.
  const auto settled_for_a_reset = [&] {
    const auto last = std::find_if(events.rbegin(), events.rend(), [](const input::InputEvent& e) {
      return e.type == T::kSuspend || e.type == T::kResume;
    });
    if (last != events.rend() && last->type == T::kSuspend) add(T::kResume);  // (adding may move the events)
    for (auto it = events.rbegin(); it != events.rend() && it->t_ms > t - 1000; ++it) {
      if (it->type == T::kReload || it->type == T::kSuspend || it->type == T::kResume) {
        t = it->t_ms + 1000 + pick.below(100);
        break;
      }
    }
  };
  // supervisor_often: the supervisor's reset three times in four (after stops from both pads).
  const auto reset_hold = [&](bool supervisor_often) {
    settled_for_a_reset();
    const bool by_supervisor = supervised && pick.below(supervisor_often ? 4 : 2) != 0;
    if (held && pick.below(4) != 0) add(T::kButton, deadman, 0);  // most often the deadman released first
    if (!held && pick.below(3) == 0) {  // now and then tapped while stopped, before the gesture: history after a reset
      add(T::kButton, deadman, 1);
      t += 1 + pick.below(60);
      add(T::kButton, deadman, 0);
      t += 40 + pick.below(100);
    }
    on_pad(by_supervisor, "back", 1);
    t += pick.below(2) == 0 ? 0 : pick.below(100);
    on_pad(by_supervisor, "start", 1);
    const auto hold = pick.below(4) == 0 ? pick.below(2000) : 1950 + pick.below(300);
    switch (pick.below(10)) {
      case 0:  // the deadman pressed during the hold
        t += pick.below(static_cast<std::uint32_t>(hold) + 1);
        add(T::kButton, deadman, 1);
        t += 10;
        add(T::kButton, deadman, 0);
        t += 2100;
        break;
      case 1:    // a stop button pressed during the hold (tapped, or held on past it)
      case 2: {  // a stop never resets, and ends the hold
        const bool stop_sup = supervised && pick.below(2) == 0;
        t += pick.below(static_cast<std::uint32_t>(hold) + 1);
        on_pad(stop_sup, "guide", 1);
        t += pick.below(2) == 0 ? 1 + pick.below(30) : 2100 + pick.below(800);
        on_pad(stop_sup, "guide", 0);
        break;
      }
      default: t += hold; break;
    }
    on_pad(by_supervisor, pick.below(2) == 0 ? "back" : "start", 0);
    t += pick.below(2) == 0 ? 0 : pick.below(60);
    on_pad(by_supervisor, "back", 0);
    on_pad(by_supervisor, "start", 0);
  };
  // Stops from both pads overlapping, each pressed again and held, released in
  // either order, the deadman pressed while one is held (issue 33's defect:
  // the supervisor's stop held on for seconds).
  const auto overlapping_stops = [&] {
    const bool first_sup = supervised && pick.below(2) == 0;
    on_pad(first_sup, "guide", 1);
    t += pick.below(80);
    if (supervised) on_pad(!first_sup, "guide", 1);
    t += 40 + pick.below(2600);
    if (pick.below(3) != 0) {  // the first let go and pressed again
      on_pad(first_sup, "guide", 0);
      t += 1 + pick.below(40);
      on_pad(first_sup, "guide", 1);
    }
    if (held) add(T::kButton, deadman, 0);
    t += 40 + pick.below(100);
    add(T::kButton, deadman, 1);
    stick();
    t += 100 + pick.below(2500);
    const bool sup_last = supervised && pick.below(2) == 0;
    if (supervised) on_pad(!sup_last, "guide", 0);
    t += pick.below(2) == 0 ? 0 : pick.below(400);
    on_pad(sup_last, "guide", 0);
  };
  // The stop buttons let go, a reset (the supervisor's on three supervised
  // ones in four: a stop pressed again while stopped is history after it), and
  // the deadman pressed afresh, the stick pushed.
  const auto reset_after_stops = [&] {
    add(T::kButton, button("guide"), 0);
    if (supervised) supervisor(T::kButton, button("guide"), 0);
    t += 40 + pick.below(100);
    reset_hold(true);
    t += 40 + pick.below(100);
    add(T::kButton, deadman, 1);
    stick();
  };
  // While stopped, the operator's pad swapped for another (or the same back),
  // or the supervisor's, then a reset chord and a deadman press on it.
  const auto swap_while_stopped = [&] {
    const bool sup = supervised && pick.below(3) == 0;
    if (pick.below(2) == 0) {  // its stop pressed again first
      on_pad(sup, "guide", 1);
      t += pick.below(100);
      on_pad(sup, "guide", 0);
    }
    pair_gap();
    const std::string other = pick.below(2) == 0 ? "B" : "A";
    if (sup) {
      supervisor(T::kDisconnect);
      pair_gap();
      supervisor(T::kConnect, {}, 0, "Sup " + other);
    } else {
      add(T::kDisconnect);
      pair_gap();
      add(T::kConnect, {}, 0, "Pad " + other);
    }
    reset_hold(false);
    t += 40 + pick.below(100);
    add(T::kButton, deadman, 1);
    stick();
  };
  // Within one frame: the deadman let go and pressed again, or the trigger (a
  // deadman on some mappings) squeezed past the panic point and back.
  const auto blip_within_a_frame = [&](input::InputKey key, int away, int back) {
    next_tick(10);
    add(key.is_button() ? T::kButton : T::kAxis, key, away);
    t += 1 + pick.below(25);
    add(key.is_button() ? T::kButton : T::kAxis, key, back);
  };

  // A wedged deadman: pressed afresh, then for about 3 s (past the simulated
  // mappings' 2 s enable timeout) nothing but a stick or the trigger jittering
  // every 100 ms, within the timeout's noise band (no change: it must time
  // out) or beyond it (a hand: it may drive on).
  const auto jitter = [&] {
    rearm();
    const bool trigger = pick.below(2) == 0;  // LT held at the middle (a trigger deadman), or the left stick
    const input::InputKey key = trigger ? arm : drive;
    const int base = trigger ? 19000 + static_cast<int>(pick.below(5000)) : static_cast<int>(pick.below(60001)) - 30000;
    const bool noise = pick.below(3) != 0;
    add(T::kAxis, key, base);
    for (int step = 0, n = 25 + static_cast<int>(pick.below(12)); step < n; ++step) {
      t += 90 + pick.below(20);
      const int size = noise ? static_cast<int>(pick.below(501)) : 1100 + static_cast<int>(pick.below(1500));
      add(T::kAxis, key, base + (step % 2 == 0 ? size : -size));
    }
  };

  // A TCP server that stops reading: neutral frames only, through its resets
  // (dropped and reopened, still not reading), whatever the operator does
  // (fresh deadman presses, the stick pushed), until it is seen reading again.
  const auto stall = [&] {
    add(T::kLinkStalled);
    for (int presses = 1 + static_cast<int>(pick.below(3)); presses > 0; --presses) {
      t += 40 + pick.below(300);
      rearm();
      t += pick.below(200);
      if (pick.below(3) == 0) {
        add(T::kLinkDown);
        pair_gap();
        add(T::kLinkUp);
      }
    }
    t += pick.below(400);
    if (pick.below(6) != 0) add(T::kLinkReading);  // now and then stalled on (to the end, or the next stall)
    if (pick.below(2) == 0) rearm();
  };

  // A toggle (X: the tool on most layouts) pressed while not enabled, or
  // while enabled and the deadman then let go and pressed again: it ends with
  // the deadman, and a press without it does nothing.
  const auto toggle_through_a_release = [&] {
    const auto tap = [&] {
      add(T::kButton, button("x"), 1);
      t += 1 + pick.below(60);
      add(T::kButton, button("x"), 0);
    };
    if (held) add(T::kButton, deadman, 0);
    t += 40 + pick.below(100);
    if (pick.below(2) == 0) {  // while not enabled
      tap();
      t += 80 + pick.below(100);
    }
    add(T::kButton, deadman, 1);
    t += 40 + pick.below(100);
    tap();
    t += 40 + pick.below(200);
    add(T::kButton, deadman, 0);
    t += 40 + pick.below(100);
    add(T::kButton, deadman, 1);
    t += 80 + pick.below(200);
  };

  // A toggled layer (the arm's or the camera's) switched on, the deadman let
  // go (the layer's click now and then made again while not enabled) and
  // pressed again, then a D-pad button tapped or a stick pushed: the layer
  // ended with the deadman, so they mean what the base layer says.
  const auto layer_through_a_release = [&] {
    if (!held) add(T::kButton, deadman, 1);
    t += 40 + pick.below(100);
    const input::InputKey toggle = layer_buttons[1 + pick.below(2)];
    for (const int v : {1, 0}) add(T::kButton, toggle, v);
    t += 40 + pick.below(100);
    add(T::kButton, deadman, 0);
    t += 40 + pick.below(100);
    if (pick.below(2) == 0) {  // clicked again while not enabled: ignored, not replayed on enabling
      for (const int v : {1, 0}) add(T::kButton, toggle, v);
      t += 80 + pick.below(100);
    }
    add(T::kButton, deadman, 1);
    t += 40 + pick.below(100);
    static constexpr std::array<std::string_view, 4> kDpad = {"dpup", "dpdown", "dpleft", "dpright"};
    for (int n = 1 + static_cast<int>(pick.below(3)); n > 0; --n) {
      if (pick.below(3) == 0) {
        add(T::kAxis, axis(pick.below(2) == 0 ? "rightx" : "righty"), 0);
        t += 40 + pick.below(80);
        add(T::kAxis, axis(pick.below(2) == 0 ? "rightx" : "righty"), pick.below(2) == 0 ? -32768 : 32767);
      } else {
        const input::InputKey b = button(kDpad[pick.below(kDpad.size())]);
        add(T::kButton, b, 1);
        t += 40 + pick.below(120);
        add(T::kButton, b, 0);
      }
      t += 40 + pick.below(100);
    }
  };

  // Speed levels (misc1 steps up, paddle1 down, on the simulated mappings
  // that have them): enabled, a stick pushed, the level stepped one to three
  // times (now and then within one frame), the stick let go and pushed again
  // (at the new level); now and then the pad or the link lost and back, then
  // the deadman pressed afresh and the stick pushed again (the initial level);
  // now and then stepped up while not enabled first (nothing).
  const auto speed = [&] {
    const input::InputKey up = button("misc1");
    const input::InputKey down = button("paddle1");
    const auto push_again = [&] {
      add(T::kAxis, drive, 0);
      t += 40 + pick.below(80);
      add(T::kAxis, drive, pick.below(2) == 0 ? -32768 : 32767);
      t += 40 + pick.below(200);
    };
    const auto step = [&](input::InputKey key) {
      add(T::kButton, key, 1);
      t += 1 + pick.below(pick.below(2) == 0 ? 30 : 200);
      add(T::kButton, key, 0);
    };
    if (pick.below(3) == 0) {  // stepped while not enabled: nothing
      if (held) add(T::kButton, deadman, 0);
      t += 40 + pick.below(80);
      step(up);
      t += 1 + pick.below(100);
    }
    if (!held || pick.below(3) == 0) rearm();
    t += 40 + pick.below(100);
    add(T::kAxis, pick.below(3) == 0 ? axis("leftx") : drive, pick.below(2) == 0 ? -32768 : 32767);
    for (int n = 1 + static_cast<int>(pick.below(3)); n > 0; --n) {
      t += pick.below(2) == 0 ? 1 + pick.below(30) : 40 + pick.below(120);
      step(pick.below(2) == 0 ? up : down);
    }
    t += 40 + pick.below(100);
    if (pick.below(3) != 0) push_again();
    const auto lost = pick.below(3);
    if (lost == 2) return;
    if (pick.below(2) == 0) step(up);  // a level above the initial one, most often, to be left behind
    t += 40 + pick.below(100);
    switch (lost) {
      case 0:
        add(T::kDisconnect);
        pair_gap();
        add(T::kConnect, {}, 0, "Pad A");
        break;
      default:
        add(T::kLinkDown);
        pair_gap();
        add(T::kLinkUp);
        break;
    }
    t += 40 + pick.below(100);
    if (pick.below(2) == 0) step(up);  // while not enabled: nothing
    rearm();
    t += 40 + pick.below(100);
    push_again();
  };

  // Pads are told apart by name (a script's identity): another name is another physical pad.
  add(T::kConnect, {}, 0, "Pad A");
  if (pick.below(4) == 0) add(T::kButton, deadman, 1);  // held at connect: not a press
  supervised = pick.below(2) == 0;                      // a supervisor's controller in every other script
  if (supervised) supervisor(T::kConnect, {}, 0, "Sup A");
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
        add(T::kConnect, {}, 0, pick.below(4) == 0 ? "Pad B" : "Pad A");
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
      switch (pick.below(45)) {
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
          add(T::kShutdown);
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
            supervisor(T::kConnect, {}, 0, pick.below(4) == 0 ? "Sup B" : "Sup A");
          }
          break;
        case 22: stop_and_press(); break;
        case 23:  // now and then reset after (the presses made while stopped are history then)
          stop_held_through_a_press();
          if (pick.below(2) == 0) reset_after_stops();
          break;
        case 24: panic_and_back(); break;
        case 25: leave_a_layer_stick_held(); break;
        case 26:  // both of an opposing pair (front articulation on most layouts) held a while
          add(T::kButton, button("dpup"), 1);
          add(T::kButton, button("dpdown"), 1);
          t += 40 + pick.below(120);
          add(T::kButton, button("dpup"), 0);
          add(T::kButton, button("dpdown"), 0);
          break;
        case 27:
        case 40:
        case 41: fire(); break;
        case 28:
        case 29:
        case 30: reset_hold(false); break;
        case 31: blip_within_a_frame(deadman, 0, 1); break;
        case 32: blip_within_a_frame(arm, 32767, pick.below(2) == 0 ? 20000 : 0); break;
        case 33:
          overlapping_stops();
          if (pick.below(3) != 0) reset_after_stops();
          break;
        case 34: swap_while_stopped(); break;
        case 35:
        case 36: jitter(); break;
        case 37:
        case 38: stall(); break;
        case 21: layer_through_a_release(); break;
        case 39: toggle_through_a_release(); break;
        case 42:
        case 43: speed(); break;
        case 44: fire(); break;
        default: rearm(); break;
      }
    }
  }
  t += pick.below(200);
  add(T::kEnd);
  return std::move(w.events);
}

}  // namespace andros::test
