#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

#include <sstream>

#include "andros/input/script_player.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/run/replay.hpp"
#include "andros/view/status_board.hpp"
#include "support/log_capture.hpp"

namespace andros::view {
namespace {

using andros::testing::LogCapture;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// A transition of the machine as the loop reports it.
run::ReportedTransition step(run::OpState from, run::OpEvent event, run::OpState to, run::Who who,
                             bool refused = false) {
  return {run::Transition{.from = from, .event = event, .to = to, .who = who, .refused = refused}, {}};
}

run::TickReport tick(std::int64_t t_ms) {
  run::TickReport r;
  r.t_ms = t_ms;
  r.result = link::SendResult::kSent;
  r.connected = true;
  r.controller = "pad";
  r.state = run::OpState::kEnabled;
  r.engine.deadman = mapping::DeadmanState::kFreshHold;
  r.engine.layer = "arm";
  r.link.state = link::LinkState::kUp;
  r.link.counters.sent = 7;
  r.data[3] = 0x5A;
  return r;
}

// Issue 28, item 6: the rate and jitter are measured since the link came up:
// the frames before it was lost are not in them.
TEST(StatusBoard, TheRateIsMeasuredSinceTheLinkCameUp) {
  RunStatusBoard board(RunStatus{});
  for (int i = 0; i < 30; ++i) board.observe(tick(i * 40));
  EXPECT_EQ(board.status().sent_timing.count, 30U);
  auto down = tick(1200);
  down.link.state = link::LinkState::kConnecting;
  down.result = link::SendResult::kDown;
  board.observe(down);
  EXPECT_EQ(board.status().sent_timing.count, 30U);  // still the last measure while down
  for (int i = 0; i < 3; ++i) board.observe(tick(5000 + i * 40));
  EXPECT_EQ(board.status().sent_timing.count, 3U);
}

TEST(EnableText, NamesWhyNotOrTheInputsHeldBack) {
  mapping::EngineStatus s;
  s.deadman = mapping::DeadmanState::kReleased;
  s.held_back = {*input::parse_axis_name("lefty")};
  EXPECT_EQ(enable_text(s), "deadman released");  // held-back inputs matter only while enabled
  s.deadman = mapping::DeadmanState::kFreshHold;
  EXPECT_EQ(enable_text(s), "enabled; at rest first: lefty");
  s.held_back.push_back(*input::parse_button_name("a"));
  EXPECT_EQ(enable_text(s), "enabled; at rest first: lefty a");
  s.held_back.clear();
  EXPECT_EQ(enable_text(s), "enabled");
}

TEST(RunStatusBoard, TheStatusIsWhatTheReportsSaid) {
  RunStatus initial;
  initial.robot = "HD1";
  initial.center = 100;
  initial.link_name = "test link";
  RunStatusBoard board(initial);
  board.observe(tick(40));
  auto s = board.status();
  EXPECT_EQ(s.robot, "HD1");  // set-up values kept
  EXPECT_EQ(s.center, 100);
  EXPECT_EQ(s.link_name, "test link");
  EXPECT_EQ(s.t_ms, 40);
  EXPECT_TRUE(s.connected);
  EXPECT_EQ(s.controller, "pad");
  EXPECT_TRUE(s.enabled());
  EXPECT_EQ(s.enable_text, "enabled");
  EXPECT_EQ(s.layer, "arm");
  EXPECT_EQ(s.link_state, link::LinkState::kUp);
  EXPECT_TRUE(s.far_end_reading);
  EXPECT_EQ(s.link.sent, 7u);
  EXPECT_EQ(s.sent[3], 0x5A);

  auto evil = tick(60);
  evil.controller = "Gamepad\n\x1B[2J";  // a controller names itself: shown and logged escaped
  board.observe(evil);
  EXPECT_EQ(board.status().controller, "Gamepad\\n\\x1B[2J");

  auto r = tick(80);
  r.controller.clear();  // a controller without a name
  r.link.far_end_reading = false;
  r.link.detail = "the link's own detail";
  board.observe(r);
  s = board.status();
  EXPECT_EQ(s.controller, "controller");
  EXPECT_FALSE(s.far_end_reading);
  EXPECT_EQ(s.link_detail.rfind("neutral frames only", 0), 0u) << s.link_detail;

  r = tick(120);
  r.state = run::OpState::kShuttingDown;  // the last step said enabled; shutting down is never enabled
  board.observe(r);
  s = board.status();
  EXPECT_TRUE(s.shutting_down());
  EXPECT_FALSE(s.enabled());
  EXPECT_EQ(s.enable_text, "sending neutral frames");
}

TEST(RunStatusBoard, ARepeatedReportMovesTheCountersAndANewKindOfControllerTheWords) {
  const LogCapture log;
  RunStatusBoard board(RunStatus{});
  auto r = tick(40);
  r.state = run::OpState::kNotEnabled;
  r.transitions = {
      step(run::OpState::kEnabled, run::OpEvent::kRelease, run::OpState::kNotEnabled, run::Who::kOperator)};
  r.engine.deadman = mapping::DeadmanState::kReleased;
  board.observe(r);
  EXPECT_EQ(board.status().enable_text, "deadman released");
  r.transitions.clear();  // reported once
  r.t_ms = 80;
  r.link.counters.sent = 8;
  r.data[3] = 0x5B;
  board.observe(r);  // the same words: only the frame, its time and the counters
  auto s = board.status();
  EXPECT_EQ(s.t_ms, 80);
  EXPECT_EQ(s.link.sent, 8u);
  EXPECT_EQ(s.sent[3], 0x5B);
  EXPECT_EQ(count(log.text(), "deadman released"), 1u);
  // The same report, but SDL now says the controller is a plain joystick: the words change.
  board.set_game_controller(false);
  board.observe(r);
  s = board.status();
  EXPECT_NE(s.enable_text.find("plain joystick"), std::string::npos) << s.enable_text;
  EXPECT_EQ(count(log.text(), "plain joystick"), 1u);
  board.set_game_controller(true);
  board.observe(r);
  EXPECT_EQ(board.status().enable_text, "deadman released");
}

TEST(RunStatusBoard, WhatTheScreenSaysIsTheOperatingStateNotTheEnginesView) {
  RunStatusBoard board(RunStatus{});
  // The engine sees the deadman freshly held, but the port does not exist:
  // nothing reaches the vehicle, and the screen must not say ENABLED.
  auto r = tick(40);
  r.state = run::OpState::kNoLink;
  r.result = link::SendResult::kDown;
  r.link.state = link::LinkState::kConnecting;
  r.link.detail = "No such file or directory";
  r.transitions = {step(run::OpState::kEnabled, run::OpEvent::kLinkDown, run::OpState::kNoLink, run::Who::kLink)};
  board.observe(r);
  auto s = board.status();
  EXPECT_FALSE(s.enabled());
  EXPECT_EQ(s.state, run::OpState::kNoLink);
  EXPECT_NE(s.enable_text.find("nothing reaches the vehicle (link No such file or directory)"), std::string::npos)
      << s.enable_text;
  // The link came back: a new link, the deadman held through it is not a
  // fresh press. The reason is the first cause, and stays when the engine
  // then reads the held deadman as held since the rebase (a consequence).
  r.state = run::OpState::kNotEnabled;
  r.transitions = {step(run::OpState::kNoLink, run::OpEvent::kLinkUp, run::OpState::kNotEnabled, run::Who::kLink)};
  board.observe(r);
  r.transitions.clear();
  s = board.status();
  EXPECT_FALSE(s.enabled());
  EXPECT_EQ(s.enable_text, "link regained: press the deadman afresh");
  r.engine.deadman = mapping::DeadmanState::kHeldNotFresh;
  board.observe(r);
  EXPECT_EQ(board.status().enable_text, "link regained: press the deadman afresh");
  for (const auto state : {run::OpState::kSuspended, run::OpState::kReloading, run::OpState::kNoController}) {
    r.state = state;
    board.observe(r);
    EXPECT_FALSE(board.status().enabled()) << run::to_string(state);
  }
}

TEST(RunStatusBoard, NotEnabledSaysTheFirstCauseNeverItsConsequence) {
  run::TickReport r;
  r.connected = true;
  r.state = run::OpState::kNotEnabled;
  r.link.state = link::LinkState::kUp;
  r.engine.deadman = mapping::DeadmanState::kHeldNotFresh;  // the held deadman, after the rebase
  using E = run::OpEvent;
  const auto said = [&r](run::OpState from, E event, run::Who who, bool refused = false) {
    return view::state_text(r, step(from, event, run::OpState::kNotEnabled, who, refused).transition);
  };
  EXPECT_EQ(said(run::OpState::kReloading, E::kReloadDone, run::Who::kLoop), "reloaded: press the deadman afresh");
  EXPECT_EQ(said(run::OpState::kReloading, E::kReloadDone, run::Who::kLoop, true),
            "reload refused, the old settings kept: press the deadman afresh");
  EXPECT_EQ(said(run::OpState::kSuspended, E::kResume, run::Who::kRequest), "resumed: press the deadman afresh");
  r.supervised = r.supervisor_connected = true;
  EXPECT_EQ(said(run::OpState::kNoController, E::kControllerUp, run::Who::kSupervisor),
            "supervisor's controller back: press the deadman afresh");
  // The operator's own controller connected: held since connect is the first cause.
  EXPECT_EQ(said(run::OpState::kNoController, E::kControllerUp, run::Who::kOperator),
            "deadman held since connect or start-up: release and press it again");
  // Released from enabled: the deadman's own state.
  r.engine.deadman = mapping::DeadmanState::kReleased;
  EXPECT_EQ(said(run::OpState::kEnabled, E::kRelease, run::Who::kOperator), "deadman released");
}

// Issue 36, item 4: the first cause is followed from the machine's
// transitions: a link lost and back is "link regained"; a link the bridge
// closed itself (a suspend) and opened again is no cause, the resume is.
TEST(FirstCause, ALinkRegainedIsACauseALinkReopenedIsNot) {
  using E = run::OpEvent;
  using S = run::OpState;
  FirstCause cause;
  EXPECT_FALSE(cause.transition());
  cause.follow({step(S::kNoLink, E::kLinkUp, S::kNotEnabled, run::Who::kLink)});  // the first link: no cause
  EXPECT_FALSE(cause.transition());
  cause.follow({step(S::kNotEnabled, E::kLinkDown, S::kNoLink, run::Who::kScript),
                step(S::kNoLink, E::kLinkUp, S::kNotEnabled, run::Who::kLink)});
  ASSERT_TRUE(cause.transition());
  EXPECT_EQ(cause.transition()->event, E::kLinkUp);
  cause.follow({step(S::kNotEnabled, E::kSuspend, S::kSuspended, run::Who::kRequest),
                step(S::kSuspended, E::kLinkDown, S::kSuspended, run::Who::kLoop),
                step(S::kSuspended, E::kResume, S::kNoLink, run::Who::kRequest)});
  cause.follow({step(S::kNoLink, E::kLinkUp, S::kNotEnabled, run::Who::kLink)});
  EXPECT_EQ(cause.transition()->event, E::kResume);
  // A step that changed no state (only a condition: the neutral frames out) is no cause.
  cause.follow({step(S::kNotEnabled, E::kNeutralSent, S::kNotEnabled, run::Who::kLoop)});
  EXPECT_EQ(cause.transition()->event, E::kResume);
}

// Issue 33, item 7: at start-up, and when a controller connects, the state
// says what enables, not the deadman's "released" as if driving had ended.
TEST(RunStatusBoard, AtStartUpNotEnabledSaysWhatEnables) {
  run::TickReport r;
  r.connected = true;
  r.state = run::OpState::kNotEnabled;
  r.link.state = link::LinkState::kUp;
  r.engine.deadman = mapping::DeadmanState::kReleased;
  EXPECT_EQ(view::state_text(r), "press the deadman to enable");
  const auto connected =
      step(run::OpState::kNoController, run::OpEvent::kControllerUp, run::OpState::kNotEnabled, run::Who::kOperator)
          .transition;
  EXPECT_EQ(view::state_text(r, connected), "controller connected: press the deadman to enable");
  r.engine.deadman = mapping::DeadmanState::kHeldNotFresh;  // held at connect: that is what to undo
  EXPECT_EQ(view::state_text(r, connected), "deadman held since connect or start-up: release and press it again");
}

/// Every report of an event script replayed through the loop with the shipped mapping_file.
std::vector<run::TickReport> replayed(const std::string& script, const std::string& mapping_file) {
  TextReader in(script, "s.events", kEventScriptLimits);
  input::ScriptPlayer player(in);
  std::vector<run::TickReport> reports;
  run::ReplayOptions options;
  options.observe = [&reports](const run::TickReport& r) { reports.push_back(r); };
  run::replay(player, mapping::Engine(mapping::load_mapping(mapping_file), options.engine), options,
              [](std::int64_t, const protocol::DataBytes&) {});
  return reports;
}

// Issue 33, item 7: the pad that stopped is named as it was at the stop: its
// unplug, or another pad plugged in, changes neither the name on the screen
// nor the log, where the stop is said once (the unplug is the controller's line).
TEST(RunStatusBoard, TheStopKeepsTheNameOfThePadThatStoppedAndAnUnplugIsNoSecondStop) {
  const auto stopped = [](const std::string& script, const std::string& mapping_file, const std::string& said) {
    const LogCapture log;
    RunStatusBoard board(RunStatus{});
    for (const auto& r : replayed(script, mapping_file)) board.observe(r);
    const auto s = board.status();
    EXPECT_EQ(s.state, run::OpState::kStopped);
    EXPECT_EQ(s.stopped_by, said);
    EXPECT_EQ(s.enable_text.rfind(said + ": ", 0), 0U) << s.enable_text;
    const auto screen = render_run_screen(s, {80, 24}).text();
    EXPECT_NE(screen.find("STOP: " + said), std::string::npos) << screen;
    EXPECT_EQ(count(log.text(), "STOP:"), 1U) << log.text();
    return log.text();
  };
  const auto operators = stopped(
      "0 connect Pad A\n40 button leftshoulder 1\n120 button guide 1\n160 button guide 0\n240 disconnect\n"
      "320 connect Pad C\n400 end\n",
      ANDROS_MAPPINGS_DIR "/hd1.yaml", "stopped by the operator (Pad A)");
  EXPECT_NE(operators.find("info: controller: none connected"), std::string::npos) << operators;
  stopped(
      "0 connect Pad A\n0 supervisor connect Pad B\n10 button leftshoulder 1\n90 supervisor button x 1\n"
      "95 supervisor button x 0\n200 supervisor disconnect\n300 end\n",
      ANDROS_TEST_DATA_DIR "/mappings/supervisor.yaml", "stopped by the supervisor (Pad B)");
}

TEST(RunStatusBoard, AWeaponsModeIsShownWhileEnabledAndLoggedOnceEachWay) {
  const LogCapture log;
  RunStatus initial;
  initial.weapons = true;
  RunStatusBoard board(initial);
  auto r = tick(40);
  r.engine.layer = "weapons";
  r.engine.weapons_mode = true;
  board.observe(r);
  EXPECT_TRUE(board.status().weapons_mode);
  r.t_ms = 80;
  board.observe(r);
  board.observe(tick(120));  // the arm layer: no weapons
  EXPECT_FALSE(board.status().weapons_mode);
  r.t_ms = 160;
  board.observe(r);
  EXPECT_TRUE(board.status().weapons_mode);
  r.t_ms = 200;
  r.state = run::OpState::kShuttingDown;  // the last step said so; a stop ends every weapons mode
  board.observe(r);
  EXPECT_FALSE(board.status().weapons_mode);
  const auto text = log.text();
  EXPECT_EQ(count(text, "warning: WEAPONS LAYER on (weapons): an armed fire input fires\n"), 2U) << text;
  EXPECT_EQ(count(text, "info: weapons layer off\n"), 1U) << text;
}

TEST(RunStatusBoard, AFrameGateTripIsAnInternalErrorLoggedAndCounted) {
  const LogCapture log;
  RunStatusBoard board(RunStatus{});
  board.observe(tick(40));
  auto r = tick(80);
  r.state = run::OpState::kStopped;
  r.gate_fault = "drive = 140 while not enabled (neutral is 128)";
  r.gate_trips = 1;
  board.observe(r);
  r.t_ms = 120;
  r.gate_fault.clear();  // the next tick: its frame passed
  board.observe(r);
  EXPECT_EQ(board.status().gate_trips, 1);
  const auto text = log.text();
  EXPECT_EQ(count(text,
                  "error: internal error: the frame gate stopped a frame that broke a safety rule (drive = 140 "
                  "while not enabled (neutral is 128)): a neutral frame was sent instead, and the bridge is "
                  "stopped\n"),
            1U)
      << text;
}

TEST(RunStatusBoard, TheSpeedLevelIsShownAndLoggedAtTheStartAndOnEachChange) {
  const LogCapture log;
  RunStatusBoard board(RunStatus{});
  auto r = tick(40);
  r.engine.speed = {0, 3, 0.25};
  board.observe(r);
  EXPECT_EQ(board.status().speed, (mapping::SpeedLevel{0, 3, 0.25}));
  r.t_ms = 80;
  board.observe(r);
  r.engine.speed = {1, 3, 0.5};
  r.t_ms = 120;
  board.observe(r);
  EXPECT_EQ(board.status().speed, (mapping::SpeedLevel{1, 3, 0.5}));
  const auto text = log.text();
  EXPECT_EQ(count(text, "info: speed level 1/3 (25%)\n"), 1U) << text;
  EXPECT_EQ(count(text, "info: speed level 2/3 (50%)\n"), 1U) << text;
}

TEST(RunStatusBoard, NoSpeedLevelsNoWordOfThem) {
  const LogCapture log;
  RunStatusBoard board(RunStatus{});
  board.observe(tick(40));
  EXPECT_EQ(log.text().find("speed"), std::string::npos) << log.text();
}

/// A tick with the supervisor's controller "Pad B" configured and connected.
run::TickReport supervised_tick(std::int64_t t_ms) {
  auto r = tick(t_ms);
  r.supervised = true;
  r.supervisor_connected = true;
  r.supervisor = "Pad B";
  return r;
}

// Who stopped and who reset: on the state line, the STOP banner's words and the log.
TEST(RunStatusBoard, StoppedSaysWhoMayResetAndHowOrHowToGoOn) {
  RunStatusBoard board(RunStatus{});
  auto r = supervised_tick(40);
  r.state = run::OpState::kStopped;
  r.stopped_by = run::StopBy::kOperator;
  r.controller = "Pad A";
  r.stopper_pad.name = "Pad A";
  r.connected = true;
  r.engine.operator_reset = "back+start";
  r.engine.supervisor_reset = "back+start";
  r.engine.reset_hold_ms = 2000;
  r.operator_may_reset = true;
  r.supervisor_may_reset = true;
  board.observe(r);
  EXPECT_EQ(board.status().enable_text,
            "stopped by the operator (Pad A): to reset, release the deadman and hold back+start 2 s (or the "
            "supervisor resets (hold back+start 2 s on its pad)); then press the deadman afresh");
  // A stop button held: nothing resets until it is let go.
  r.t_ms = 80;
  r.engine.stop_held = true;
  board.observe(r);
  EXPECT_EQ(board.status().enable_text,
            "stopped by the operator (Pad A): a stop button is held: nothing resets until every stop button is "
            "released");
  // Another pad took the operator's role: it may not reset; the screen says how to go on.
  r.t_ms = 120;
  r.engine.stop_held = false;
  r.operator_may_reset = false;
  r.controller = "Pad C";
  r.stopper_pad = input::PadIdentity{"Pad A", "/dev/input/event5", "", ""};
  board.observe(r);
  EXPECT_EQ(board.status().enable_text,
            "stopped by the operator (Pad A): this controller (Pad C) did not stop, Pad A (path /dev/input/event5) "
            "did: the supervisor resets (hold back+start 2 s on its pad); then press the deadman afresh");
  // With no supervisor to reset it: restart.
  r.t_ms = 160;
  r.supervised = false;
  r.supervisor_may_reset = false;
  board.observe(r);
  EXPECT_EQ(board.status().enable_text,
            "stopped by the operator (Pad A): this controller (Pad C) did not stop, Pad A (path /dev/input/event5) "
            "did: restart the bridge to go on");
}

TEST(RunStatusBoard, WhoStoppedAndWhoResetAreSaidAndLogged) {
  const LogCapture log;
  RunStatusBoard board(RunStatus{});
  auto r = supervised_tick(40);
  board.observe(r);
  r.t_ms = 80;
  r.state = run::OpState::kStopped;
  r.transitions = {
      step(run::OpState::kEnabled, run::OpEvent::kSupervisorStop, run::OpState::kStopped, run::Who::kSupervisor)};
  r.stopped_by = run::StopBy::kSupervisor;
  r.supervisor_may_reset = true;
  r.engine.operator_reset = "back+start";
  r.engine.supervisor_reset = "back+start";
  r.engine.reset_hold_ms = 2000;
  r.stopper_pad.name = "Pad B";
  board.observe(r);
  auto s = board.status();
  EXPECT_EQ(s.stopped_by, "stopped by the supervisor (Pad B)");
  // The supervisor's own instructions, never the operator's (issue 33).
  EXPECT_EQ(s.enable_text,
            "stopped by the supervisor (Pad B): only the supervisor resets it: hold back+start 2 s on its pad; then "
            "press the deadman afresh");
  // The hold's progress, in place of the instructions, and never in the log (it moves every tick).
  r.transitions.clear();
  r.t_ms = 100;
  r.engine.reset_hold = mapping::ResetHold{input::Pad::kSupervisor, 1200, 2000};
  board.observe(r);
  EXPECT_EQ(board.status().reset_progress,
            "resetting: 1.2 of 2.0 s (the supervisor's back+start held; a stop button or the deadman ends it)");
  EXPECT_EQ(log.text().find("resetting"), std::string::npos) << log.text();
  r.engine.reset_hold.reset();
  r.t_ms = 120;
  r.state = run::OpState::kNotEnabled;
  r.transitions = {
      step(run::OpState::kStopped, run::OpEvent::kSupervisorReset, run::OpState::kNotEnabled, run::Who::kSupervisor)};
  r.stopped_by.reset();
  r.stopper_pad = {};
  r.reset_by = run::StopBy::kSupervisor;
  r.engine.deadman = mapping::DeadmanState::kReleased;
  board.observe(r);
  s = board.status();
  EXPECT_EQ(s.stopped_by, "");
  EXPECT_EQ(s.enable_text, "stop reset by the supervisor: press the deadman afresh");
  r.t_ms = 160;
  r.state = run::OpState::kStopped;
  r.transitions = {
      step(run::OpState::kNotEnabled, run::OpEvent::kOperatorStop, run::OpState::kStopped, run::Who::kOperator)};
  r.reset_by.reset();
  r.stopped_by = run::StopBy::kOperator;
  r.stopper_pad.name = "pad";
  r.operator_may_reset = true;
  board.observe(r);
  EXPECT_EQ(board.status().stopped_by, "stopped by the operator (pad)");
  // The pad that stopped unplugged: its name is kept for the stop, and it is no second STOP line.
  r.t_ms = 200;
  r.transitions = {
      step(run::OpState::kStopped, run::OpEvent::kControllerDown, run::OpState::kStopped, run::Who::kOperator)};
  r.connected = false;
  r.controller.clear();
  // r.stopper_pad stays the pad that stopped
  r.operator_may_reset = false;
  board.observe(r);
  EXPECT_EQ(board.status().stopped_by, "stopped by the operator (pad)");
  const auto text = log.text();
  EXPECT_EQ(count(text, "warning: STOP: stopped by the supervisor (Pad B): only the supervisor resets it"), 1U) << text;
  EXPECT_EQ(count(text, "info: not enabled: stop reset by the supervisor: press the deadman afresh\n"), 1U) << text;
  EXPECT_EQ(count(text, "warning: STOP: stopped by the operator (pad): to reset"), 1U) << text;
  EXPECT_EQ(count(text, "warning: STOP:"), 2U) << text;
  EXPECT_EQ(count(text, "info: stopped: stopped by the operator (pad): the controller that stopped is gone"), 1U)
      << text;
}

// The supervisor's controller: on the board, in the log once per change, and
// named in the state when it is what is missing.
TEST(RunStatusBoard, TheSupervisorsControllerIsShownAndItsComingAndGoingLogged) {
  const LogCapture log;
  RunStatusBoard board(RunStatus{});
  auto r = supervised_tick(40);
  r.engine.supervisor_stop = true;
  r.engine.consent = mapping::ConsentState::kGiven;
  board.observe(r);
  auto s = board.status();
  EXPECT_TRUE(s.supervised);
  EXPECT_EQ(s.supervisor, "Pad B");
  EXPECT_TRUE(s.supervisor_stop);
  EXPECT_EQ(s.consent, mapping::ConsentState::kGiven);
  r.t_ms = 80;
  board.observe(r);
  r.t_ms = 120;
  r.supervisor_connected = false;
  r.supervisor.clear();
  r.state = run::OpState::kNoController;
  board.observe(r);
  s = board.status();
  EXPECT_FALSE(s.supervisor_connected);
  EXPECT_FALSE(s.supervisor_stop);  // a lost controller holds nothing
  EXPECT_EQ(s.enable_text, "connect the supervisor's controller, then press the deadman afresh");
  r.t_ms = 160;
  r.connected = false;
  board.observe(r);
  EXPECT_EQ(board.status().enable_text, "connect a controller, then press the deadman");
  const auto text = log.text();
  EXPECT_EQ(count(text, "info: supervisor's controller: Pad B\n"), 1U) << text;
  EXPECT_EQ(count(text, "warning: supervisor's controller: none connected: nothing moves without it\n"), 1U) << text;

  const LogCapture quiet;  // without a supervisor, nothing is said of one
  RunStatusBoard alone(RunStatus{});
  alone.observe(tick(40));
  EXPECT_EQ(quiet.text().find("supervisor"), std::string::npos) << quiet.text();
}

TEST(RunStatusBoard, AReloadNamesTheNewMappingAndWeaponsOnTheScreen) {
  RunStatus initial;
  initial.robot = "HD1";
  initial.mapping_file = "/m/hd1.yaml";
  RunStatusBoard board(initial);
  board.set_mapping("RAV", "/m/rav.yaml", true, 100);
  const auto s = board.status();
  EXPECT_EQ(s.robot, "RAV");
  EXPECT_EQ(s.mapping_file, "/m/rav.yaml");
  EXPECT_TRUE(s.weapons);
  EXPECT_EQ(s.center, 100);
  const auto text = render_run_screen(s, {80, 24}).text();
  EXPECT_NE(text.find("WEAPONS ENABLED"), std::string::npos) << text;
  EXPECT_NE(text.find("mapping     /m/rav.yaml\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace andros::view
