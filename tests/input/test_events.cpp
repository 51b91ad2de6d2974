#include <gtest/gtest.h>

#include "andros/base/error.hpp"
#include "andros/input/events.hpp"

namespace andros::input {
namespace {

using T = InputEvent::Type;

// The first example of docs/event-scripts.md.
TEST(EventScript, TheDocumentedExampleParses) {
  const auto events = parse_event_script(
      "# t_ms  event       arguments\n"
      "0       connect     Xbox 360 Controller\n"
      "100     button      leftshoulder 1\n"
      "120     axis        lefty -32768   # full forward\n"
      "\n"
      "900     button      leftshoulder 0\n"
      "950     disconnect\n"
      "2000    end\n",
      "x.events");
  ASSERT_EQ(events.size(), 6U);
  EXPECT_EQ(events[0].type, T::kConnect);
  EXPECT_EQ(events[0].name, "Xbox 360 Controller");
  EXPECT_EQ(events[1].type, T::kButton);
  EXPECT_EQ(events[1].key, *parse_button_name("leftshoulder"));
  EXPECT_EQ(events[1].value, 1);
  EXPECT_EQ(events[2].type, T::kAxis);
  EXPECT_EQ(events[2].value, -32768);
  EXPECT_EQ(events[2].line, 4);
  EXPECT_EQ(events[4].type, T::kDisconnect);
  EXPECT_EQ(events[5].type, T::kEnd);
  EXPECT_EQ(events[5].t_ms, 2000);
}

TEST(EventScript, JoystickButtonsAxesAndHats) {
  const auto events = parse_event_script("0 connect\n1 button 3 1\n2 axis 5 100\n3 hat 1 leftup\n", "j");
  ASSERT_EQ(events.size(), 4U);
  EXPECT_EQ(events[1].key, (InputKey{InputKind::kJoyButton, 3}));
  EXPECT_EQ(events[2].key, (InputKey{InputKind::kJoyAxis, 5}));
  EXPECT_EQ(events[3].key, (InputKey{InputKind::kHat, 4}));
  EXPECT_EQ(events[3].value, 9);
}

struct BadScript {
  const char* text;
  int line;
  int column;
  const char* message;
};

class EventScriptErrors : public ::testing::TestWithParam<BadScript> {};

TEST_P(EventScriptErrors, NameFileLineAndColumn) {
  const auto& c = GetParam();
  try {
    parse_event_script(c.text, "bad.events");
    FAIL() << "accepted: " << c.text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.pos().file, "bad.events");
    EXPECT_EQ(e.pos().line, c.line);
    EXPECT_EQ(e.pos().column, c.column);
    EXPECT_EQ(e.message(), c.message);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Catalogue, EventScriptErrors,
    ::testing::Values(
        BadScript{"0 connect\n10 jump\n", 2, 4,
                  "unknown event 'jump' (expected connect, disconnect, button, axis, hat, end, link, suspend, resume, "
                  "reload, stop or supervisor)"},
        BadScript{"0 connect\n10 link sideways\n", 2, 9,
                  "unknown link event 'sideways' (expected down, up, taken, stalled or reading)"},
        BadScript{"0 connect\n10 link\n", 2, 4, "expected 'link down|up|taken|stalled|reading'"},
        BadScript{"0 connect\n10 suspend now\n", 2, 12, "expected 'suspend'"},
        BadScript{"0 connect\n10 reload a.yaml b.yaml\n", 2, 18, "expected 'reload [MAPPING]'"},
        BadScript{"0 connect\n100 button a 1\n50 button a 0\n", 3, 1,
                  "time 50 ms goes backwards (previous event at 100 ms)"},
        BadScript{"0 connect\n1 button trigger 1\n", 2, 10, "unknown button 'trigger'"},
        BadScript{"0 connect\n1 axis leftz 0\n", 2, 8, "unknown axis 'leftz'"},
        BadScript{"0 connect\n1 axis leftx 32768\n", 2, 14, "axis value 32768 is out of range -32768..32767"},
        BadScript{"0 connect\n1 button a 2\n", 2, 12, "button value 2 is out of range 0..1"},
        BadScript{"0 connect\n1 button a\n", 2, 3, "expected 'button NAME 0|1'"},
        BadScript{"0 connect\n1 button a 1 1\n", 2, 14, "expected 'button NAME 0|1'"},
        BadScript{"x connect\n", 1, 1, "time 'x' is not a whole number"},
        BadScript{"-5 connect\n", 1, 1, "time -5 is out of range 0..4611686018427387903"},
        BadScript{"0 hat 0 sideways\n", 1, 9, "unknown hat position 'sideways'"},
        BadScript{"0 end\n5 connect\n", 2, 1, "event after 'end'"}, BadScript{"0 end now\n", 1, 7, "expected 'end'"},
        BadScript{"12\n", 1, 1, "missing event after the time"},
        BadScript{"0 supervisor stop\n", 1, 14,
                  "'supervisor' takes connect, disconnect, button, axis or hat, not 'stop': the other events are "
                  "the run's, not a controller's"},
        BadScript{"0 supervisor end\n", 1, 14,
                  "'supervisor' takes connect, disconnect, button, axis or hat, not 'end': the other events are "
                  "the run's, not a controller's"},
        BadScript{"0 supervisor\n", 1, 3, "missing event after 'supervisor'"},
        BadScript{"0 supervisor button a\n", 1, 14, "expected 'button NAME 0|1'"},
        BadScript{"0 supervisor button a 1 1\n", 1, 25, "expected 'button NAME 0|1'"},
        BadScript{"0 supervisor axis leftx 40000\n", 1, 25, "axis value 40000 is out of range -32768..32767"},
        BadScript{"0 connect\n86400001 end\n", 2, 1,
                  "time 86400001 ms is past 24 h (86400000 ms), the longest an event script may last"}),
    [](const auto& param_info) { return "case" + std::to_string(param_info.index); });

// A controller names itself (its USB descriptors): a name holding newlines
// written by `record` stays one connect line and reads back as the same bytes.
TEST(EventScript, AControllerNameIsOneLineOfPrintableText) {
  const std::string hostile = "Gamepad\n500 button leftshoulder 0\n600 button leftshoulder 1\n700 axis lefty -32768\n#";
  InputEvent connect;
  connect.type = T::kConnect;
  connect.name = hostile;
  const auto line = format_event(connect);
  EXPECT_EQ(line,
            "0       connect     Gamepad\\n500 button leftshoulder 0\\n600 button leftshoulder 1\\n700 axis lefty "
            "-32768\\n\\x23");
  const auto events = parse_event_script(line + "\n900 end\n", "recorded.events");
  ASSERT_EQ(events.size(), 2U);
  EXPECT_EQ(events[0].name, hostile);
  EXPECT_EQ(events[1].type, T::kEnd);

  for (const std::string& name : {std::string("pad\0\x1B[2J\\ \xFF", 10), std::string("Manette \xC3\xA9 #2")}) {
    connect.name = name;
    EXPECT_EQ(parse_event_script(format_event(connect) + "\n", "x.events").at(0).name, name) << format_event(connect);
  }
}

// Which physical pad a connect is: `{path=P serial=S guid=G}` before the
// name, written and read back, hostile bytes and spaces escaped; a name that
// begins with a brace is not taken for one.
TEST(EventScript, AConnectNamesItsPhysicalPad) {
  InputEvent connect;
  connect.type = T::kConnect;
  connect.name = "Pad \xFF";
  connect.device = PadIdentity{"", "/dev/input/event 5", "S/N\n7", "030000005e040000"}.fields();
  const auto line = format_event(connect);
  EXPECT_EQ(line, "0       connect     {path=/dev/input/event\\x205 serial=S/N\\n7 guid=030000005e040000} Pad \\xFF");
  const auto back = parse_event_script(line + "\n", "x.events").at(0);
  EXPECT_EQ(back.name, "Pad \xFF");
  EXPECT_EQ(back.device, connect.device);
  InputState state;
  state.apply(back);
  EXPECT_EQ(state.operator_pad().identity(),
            (PadIdentity{"Pad \xFF", "/dev/input/event 5", "S/N\n7", "030000005e040000"}));
  // A name that begins with a brace stays a name.
  connect.device.clear();
  connect.name = "{guid=1} Pad";
  EXPECT_EQ(format_event(connect), "0       connect     \\x7bguid=1} Pad");
  const auto named = parse_event_script(format_event(connect) + "\n", "x.events").at(0);
  EXPECT_EQ(named.name, "{guid=1} Pad");
  EXPECT_EQ(named.device, "");
  // Fields that are not an identity are refused at their line.
  EXPECT_THROW(parse_event_script("0 connect {colour=red} Pad\n", "x.events"), InputError);
  EXPECT_THROW(parse_event_script("0 connect {path=/dev/x Pad\n", "x.events"), InputError);
}

// The same physical pad, as far as can be told: a serial on both decides with
// the GUID; without, the path, GUID and name together (a new path is another pad).
TEST(PadIdentity, TheSamePadOnlyWhenItCanBeTold) {
  const PadIdentity a{"Pad", "/dev/input/event5", "", "0300"};
  EXPECT_TRUE(a.same_pad(a));
  EXPECT_FALSE(a.same_pad(PadIdentity{"Pad", "/dev/input/event6", "", "0300"}));
  EXPECT_FALSE(a.same_pad(PadIdentity{"Pad 2", "/dev/input/event5", "", "0300"}));
  const PadIdentity s{"Pad", "/dev/input/event5", "SN1", "0300"};
  EXPECT_TRUE(s.same_pad(PadIdentity{"Pad", "/dev/input/event9", "SN1", "0300"}));  // replugged elsewhere
  EXPECT_FALSE(s.same_pad(PadIdentity{"Pad", "/dev/input/event5", "SN2", "0300"}));
  EXPECT_FALSE(s.same_pad(a));  // one with a serial, one without: not told to be the same
  PadRegistry pads;
  const auto first = pads.id_of(s);
  EXPECT_EQ(pads.id_of(PadIdentity{"Pad", "/dev/input/event9", "SN1", "0300"}), first);
  EXPECT_NE(pads.id_of(a), first);
  EXPECT_EQ(pads.id_of(PadIdentity{}), kNoPad);
  pads.keep({first});
  EXPECT_EQ(pads.identity(first), s);
  EXPECT_TRUE(pads.identity(first + 1).empty());  // forgotten
}

TEST(EventScript, AControllerNameWithARawControlByteIsRefused) {
  const auto error = [](const std::string& script) {
    try {
      parse_event_script(script, "x.events");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error(std::string("0 connect pad\0name\n", 19)),
            "x.events:1:11: error: controller name 'pad\\x00name' is not one line of printable text (a control byte or "
            "invalid UTF-8 is written \\xNN)");
  EXPECT_NE(error("0 connect \x1B[31mred\n").find("is not one line of printable text"), std::string::npos);
  EXPECT_EQ(error("0 connect pad\\q\n"),
            "x.events:1:14: error: unknown escape '\\\\q' (a backslash starts \\\\, \\n, \\r, \\t or \\xNN)");
  EXPECT_EQ(parse_event_script("0 connect pad\\x00name\n", "x.events").at(0).name, std::string("pad\0name", 8));
}

// `T supervisor EVENT`: the same events, for the supervisor's controller.
TEST(EventScript, SupervisorLinesAddressTheSecondController) {
  const auto events = parse_event_script(
      "0 connect Pad A\n"
      "0 supervisor connect Pad B  # the supervisor's\n"
      "10 supervisor button guide 1\n"
      "20 supervisor axis lefttrigger 32767\n"
      "30 supervisor hat 0 up\n"
      "40 button guide 1\n"
      "50 supervisor disconnect\n",
      "s.events");
  ASSERT_EQ(events.size(), 7U);
  EXPECT_EQ(events[0].pad, Pad::kOperator);
  EXPECT_EQ(events[1].pad, Pad::kSupervisor);
  EXPECT_EQ(events[1].type, T::kConnect);
  EXPECT_EQ(events[1].name, "Pad B");
  EXPECT_EQ(events[2].type, T::kButton);
  EXPECT_EQ(events[2].key, *parse_button_name("guide"));
  EXPECT_EQ(events[2].pad, Pad::kSupervisor);
  EXPECT_EQ(events[3].type, T::kAxis);
  EXPECT_EQ(events[3].value, 32767);
  EXPECT_EQ(events[4].type, T::kHat);
  EXPECT_EQ(events[4].pad, Pad::kSupervisor);
  EXPECT_EQ(events[5].pad, Pad::kOperator);
  EXPECT_EQ(events[6].type, T::kDisconnect);
  EXPECT_EQ(events[6].pad, Pad::kSupervisor);
}

TEST(EventScript, SupervisorLinesFormatAndReadBack) {
  const std::string text =
      "0       supervisor connect     Pad B\n"
      "10      supervisor button      guide 1\n"
      "20      supervisor axis        lefty -32768\n"
      "30      supervisor hat         0 up\n"
      "40      supervisor disconnect\n"
      "50      supervisor connect\n";
  std::string again;
  for (const auto& e : parse_event_script(text, "f")) again += format_event(e) + "\n";
  EXPECT_EQ(again, text);
}

TEST(EventScript, AScriptAddressingTheSupervisorSaysSo) {
  TextReader with("0 connect\n# 5 supervisor connect: a comment is not a line\n100 supervisor connect\n200 end\n",
                  "w.events", kEventScriptLimits);
  EXPECT_TRUE(addresses_supervisor(with));
  EXPECT_EQ(with.line_number(), 0);  // rewound
  EXPECT_EQ(*with.next_line(), "0 connect");
  TextReader without("0 connect\n# 5 supervisor connect\n100 button a 1\n", "n.events", kEventScriptLimits);
  EXPECT_FALSE(addresses_supervisor(without));
  EXPECT_EQ(without.line_number(), 0);
}

TEST(EventScript, LastsAtMostADay) {
  EXPECT_EQ(parse_event_script("0 connect\n86400000 end\n", "day.events").back().t_ms, kMaxScriptMs);
}

TEST(EventScript, ALineLongerThanTheLimitIsAnError) {
  const std::string name(kMaxLineBytes, 'x');  // with "0 connect " in front: over the limit
  try {
    parse_event_script("0 end\n0 connect " + name + "\n", "long.events");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "long.events:2: error: line longer than 4 KiB (the limit for an event script)");
  }
}

TEST(EventScript, CheckedWholeBeforeItPlays) {
  // The bad line is far past anything a player would read ahead.
  TextReader bad("0 connect\n100 end\n200 button a 1\n", "after.events", kEventScriptLimits);
  EXPECT_THROW((void)checked_event_script(std::move(bad)), InputError);
  auto good = checked_event_script(TextReader("0 connect\n100 end\n", "ok.events", kEventScriptLimits));
  EXPECT_EQ(good.line_number(), 0);  // rewound
  EXPECT_EQ(*good.next_line(), "0 connect");
}

TEST(EventScript, FormatReadsBack) {
  const std::string text =
      "0       connect     Xbox 360 Controller\n"
      "100     button      leftshoulder 1\n"
      "120     axis        lefty -32768\n"
      "130     button      7 1\n"
      "140     hat         2 rightdown\n"
      "950     disconnect\n"
      "1000    link stalled\n"
      "1100    link reading\n"
      "2000    end\n";
  std::string again;
  for (const auto& e : parse_event_script(text, "f")) again += format_event(e) + "\n";
  EXPECT_EQ(again, text);
}

// Every event written back stays inside the line bound (a fuzz finding: a
// connect line just under 4 KiB came back longer once its columns were padded).
TEST(EventScript, ControllerNamesAreBoundedSoWrittenEventsReadBack) {
  const std::string longest(kMaxControllerNameBytes, 'x');
  const auto events = parse_event_script("0 connect " + longest + "\n", "f");
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].name, longest);
  try {
    (void)parse_event_script("0 connect " + longest + "y\n", "f");
    FAIL() << "a longer name was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.pos().line, 1);
    EXPECT_EQ(e.pos().column, 11);
    EXPECT_NE(e.message().find("controller name longer than 256 bytes"), std::string::npos) << e.what();
  }
  InputEvent from_sdl;  // a name as long as a device may report goes out cut to the bound
  from_sdl.type = T::kConnect;
  from_sdl.name = std::string(5000, 'n');
  const auto line = format_event(from_sdl);
  EXPECT_LT(line.size(), kMaxLineBytes);
  EXPECT_EQ(parse_event_script(line + "\n", "f")[0].name, std::string(kMaxControllerNameBytes, 'n'));
}

InputEvent ev(std::int64_t t, T type, std::string_view name = "", int value = 0) {
  InputEvent e;
  e.t_ms = t;
  e.type = type;
  if (type == T::kButton) e.key = *parse_button_name(name);
  if (type == T::kAxis) e.key = *parse_axis_name(name);
  if (type == T::kHat) e.key = InputKey{InputKind::kHat, 0};
  e.value = value;
  return e;
}

TEST(InputState, HeldAtConnectIsNotAPress) {
  InputState s;
  const auto lb = *parse_button_name("leftshoulder");
  s.apply(ev(0, T::kConnect));
  s.apply(ev(0, T::kButton, "leftshoulder", 1));
  EXPECT_TRUE(s.button(lb).down);
  EXPECT_EQ(s.button(lb).presses, 0U);
  s.apply(ev(40, T::kButton, "leftshoulder", 0));
  s.apply(ev(80, T::kButton, "leftshoulder", 1));
  EXPECT_EQ(s.button(lb).presses, 1U);
}

TEST(InputState, TapsCountAndConnectStartsAfresh) {
  InputState s;
  const auto a = *parse_button_name("a");
  s.apply(ev(0, T::kConnect));
  EXPECT_EQ(s.connection(), 1U);
  for (int i = 0; i < 3; ++i) {
    s.apply(ev(10 + i, T::kButton, "a", 1));
    s.apply(ev(10 + i, T::kButton, "a", 0));
  }
  EXPECT_EQ(s.button(a).presses, 3U);
  EXPECT_FALSE(s.button(a).down);
  s.apply(ev(20, T::kAxis, "leftx", -32768));
  EXPECT_EQ(s.axis(*parse_axis_name("leftx")), -32768);
  s.apply(ev(30, T::kDisconnect));
  EXPECT_FALSE(s.connected());
  EXPECT_EQ(s.axis(*parse_axis_name("leftx")), 0);
  s.apply(ev(35, T::kButton, "a", 1));  // stale event from a lost controller
  EXPECT_FALSE(s.button(a).down);
  s.apply(ev(40, T::kConnect));
  EXPECT_EQ(s.connection(), 2U);
  EXPECT_EQ(s.button(a).presses, 0U);
}

TEST(InputState, EveryChangeBetweenTwoTicksIsKept) {
  InputState s;
  const auto lb = *parse_button_name("leftshoulder");
  const auto lt = *parse_axis_name("lefttrigger");
  s.apply(ev(0, T::kConnect));
  s.apply(ev(0, T::kButton, "leftshoulder", 1));  // held at connect: neither a press nor, later, a release of it
  s.apply(ev(0, T::kAxis, "lefttrigger", 30000));
  EXPECT_EQ(s.button(lb).releases, 0U);
  EXPECT_EQ(s.axis_span(lt), (AxisSpan{30000, 30000}));  // the state at connect spans its value alone
  s.begin_tick();
  // Released at 90 ms and pressed again at 110 ms, within one tick: down at its end, and one release.
  s.apply(ev(90, T::kButton, "leftshoulder", 0));
  s.apply(ev(110, T::kButton, "leftshoulder", 1));
  EXPECT_TRUE(s.button(lb).down);
  EXPECT_EQ(s.button(lb).presses, 1U);
  EXPECT_EQ(s.button(lb).releases, 1U);
  // A trigger let go and squeezed again: its span keeps where it went.
  s.apply(ev(95, T::kAxis, "lefttrigger", 0));
  s.apply(ev(105, T::kAxis, "lefttrigger", 32767));
  s.apply(ev(115, T::kAxis, "lefttrigger", 30000));
  EXPECT_EQ(s.axis(lt), 30000);
  EXPECT_EQ(s.axis_span(lt), (AxisSpan{0, 32767}));
  // The next tick starts from the value now; counts go on.
  s.begin_tick();
  EXPECT_EQ(s.axis_span(lt), (AxisSpan{30000, 30000}));
  EXPECT_EQ(s.button(lb).releases, 1U);
}

TEST(InputState, HatDirectionsAreButtons) {
  InputState s;
  s.apply(ev(0, T::kConnect));
  s.apply(ev(5, T::kHat, "", 9));  // leftup
  EXPECT_EQ(s.hat(0), 9);
  EXPECT_TRUE(s.button(*parse_button_name("hat0up")).down);
  EXPECT_TRUE(s.button(*parse_button_name("hat0left")).down);
  EXPECT_FALSE(s.button(*parse_button_name("hat0down")).down);
  EXPECT_EQ(s.button(*parse_button_name("hat0up")).presses, 1U);
}

TEST(InputNames, RoundTrip) {
  for (const auto name : {"a", "touchpad", "dpleft", "0", "17", "hat0up", "hat3left"}) {
    const auto key = parse_button_name(name);
    ASSERT_TRUE(key) << name;
    EXPECT_EQ(input_name(*key), name);
  }
  for (const auto name : {"leftx", "righttrigger", "4"}) EXPECT_EQ(input_name(*parse_axis_name(name)), name);
  EXPECT_FALSE(parse_button_name("A"));
  EXPECT_FALSE(parse_button_name("hat"));
  EXPECT_FALSE(parse_button_name("hatup"));
  EXPECT_FALSE(parse_button_name("256"));
  EXPECT_FALSE(parse_axis_name("lefttrig"));
}

}  // namespace
}  // namespace andros::input
