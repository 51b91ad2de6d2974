#pragma once
// The fault simulation's scripts for its TCP runs (docs/testing.md, "Fault
// simulation"): an operator driving on the simulated HD1 (deadman LB, the left
// stick), and a TCP server (tcp_server.hpp: the script's link events are
// its own) that stalls for up to 7 s, now and then resets or closes its
// connection and refuses new ones for up to 4 s (the back-off grows), and
// reads again, or not. Through each stall the operator keeps pressing the
// deadman afresh and moving the stick: the presses the link's distrust of a
// server that stalled must hold to neutral frames.

#include <cstdint>
#include <utility>
#include <vector>

#include "andros/input/events.hpp"
#include "oracle/script_writer.hpp"

namespace andros::test {

template <typename Choices>
std::vector<input::InputEvent> tcp_script(Choices& pick) {
  using T = input::InputEvent::Type;
  const input::InputKey deadman = *input::parse_button_name("leftshoulder");
  const input::InputKey drive = *input::parse_axis_name("lefty");
  ScriptWriter<Choices> w(pick, deadman);
  auto& t = w.t;
  const auto add = [&w](T type, input::InputKey key = {}, int value = 0) { w.add(type, key, value); };

  // For ms: the stick moved (past the enable timeout's band) or the deadman let go and pressed afresh, again and again.
  bool forward = true;
  const auto drive_for = [&](std::int64_t ms) {
    const std::int64_t until = t + ms;
    while (t < until) {
      t += 150 + pick.below(450);
      if (pick.below(3) == 0) {
        add(T::kButton, deadman, 0);
        t += 40 + pick.below(160);
        add(T::kButton, deadman, 1);
      } else {
        forward = !forward;
        add(T::kAxis, drive, forward ? -32768 : -16000);
      }
    }
  };

  add(T::kConnect);
  t = 20;
  add(T::kButton, deadman, 1);
  t += 40;
  add(T::kAxis, drive, -32768);
  drive_for(500 + pick.below(1500));
  for (int segments = 3 + static_cast<int>(pick.below(4)); segments > 0; --segments) {
    switch (pick.below(8)) {
      case 0:
      case 1:
      case 2:
      case 3:
        add(T::kLinkStalled);
        drive_for(1000 + pick.below(6000));
        if (pick.below(3) == 0) {  // reset during the stall, and a new connection to a server still not reading
          add(pick.below(2) == 0 ? T::kLinkDown : T::kLinkTaken);
          drive_for(50 + pick.below(2000));
          add(T::kLinkUp);
          drive_for(500 + pick.below(3000));
        }
        if (pick.below(6) != 0) add(T::kLinkReading);
        drive_for(300 + pick.below(2000));
        break;
      case 4:
      case 5:
        add(pick.below(2) == 0 ? T::kLinkDown : T::kLinkTaken);
        drive_for(100 + pick.below(4000));
        add(T::kLinkUp);
        drive_for(500 + pick.below(2000));
        break;
      case 6:
        add(T::kSuspend);
        t += 100 + pick.below(900);
        add(T::kResume);
        drive_for(300 + pick.below(1000));
        break;
      default: drive_for(500 + pick.below(3000)); break;
    }
  }
  t += pick.below(200);
  add(T::kEnd);
  return std::move(w.events);
}

}  // namespace andros::test
