// Roles that cannot swap: the operator's and the supervisor's controllers are
// two physical pads, whatever order SDL lists them in after a replug.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>

#include "andros/input/sdl_input.hpp"
#include "andros/link/fault_link.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/record/record_sink.hpp"
#include "andros/record/recorded_loop.hpp"
#include "andros/view/status_board.hpp"
#include "support/log_capture.hpp"
#include "support/temp_dir.hpp"
#include "support/virtual_device.hpp"

namespace andros::input {
namespace {

using test::VirtualDevice;

constexpr InputKey kA{InputKind::kPadButton, SDL_CONTROLLER_BUTTON_A};
constexpr InputKey kB{InputKind::kPadButton, SDL_CONTROLLER_BUTTON_B};

/// Two pads of one model: one name, one vendor and product, so one GUID.
VirtualDevice twin() { return VirtualDevice::pad("Twin Pad", 20); }

class PadRolesTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::use_dummy_video(); }

  void SetUp() override {
    if (SDL_NumJoysticks() > 0) GTEST_SKIP() << "a real controller is attached";
  }

  void tick(SdlInput& input) { input.pump(tick_, now_ += 40); }

  /// Each pad presses its own button (the operator's pad A, the supervisor's
  /// B) and releases it: true when each press reached its own role only.
  bool roles_kept(SdlInput& input, VirtualDevice& operators, VirtualDevice& supervisors) {
    operators.button(SDL_CONTROLLER_BUTTON_A, true);
    supervisors.button(SDL_CONTROLLER_BUTTON_B, true);
    tick(input);
    const bool kept = state_.button(kA).down && !state_.button(kB).down && state_.supervisor().button(kB).down &&
                      !state_.supervisor().button(kA).down;
    operators.button(SDL_CONTROLLER_BUTTON_A, false);
    supervisors.button(SDL_CONTROLLER_BUTTON_B, false);
    tick(input);
    return kept;
  }

  /// The first tick: each role on its own pad.
  void connect_both(SdlInput& input, VirtualDevice& operators, VirtualDevice& supervisors) {
    tick(input);
    ASSERT_TRUE(state_.connected());
    ASSERT_TRUE(state_.supervisor().connected());
    EXPECT_TRUE(roles_kept(input, operators, supervisors));
  }

  /// Unplugs both pads, then plugs the supervisor's back first (SDL now lists
  /// it first), then the operator's; `tag` gives each new pad what SDL would
  /// report of that unit. Neither role may take the other's pad.
  void replug_in_the_other_order(SdlInput& input, std::optional<VirtualDevice>& operators,
                                 std::optional<VirtualDevice>& supervisors,
                                 const std::function<void(const VirtualDevice&, Pad)>& tag) {
    operators.reset();
    supervisors.reset();
    tick(input);
    supervisors.emplace(twin());
    tag(*supervisors, Pad::kSupervisor);
    tick(input);
    EXPECT_FALSE(state_.connected()) << "the operator's role took the supervisor's pad";
    EXPECT_TRUE(state_.supervisor().connected());
    operators.emplace(twin());
    tag(*operators, Pad::kOperator);
    tick(input);
    ASSERT_TRUE(state_.connected());
    EXPECT_TRUE(roles_kept(input, *operators, *supervisors));
  }

  /// options, with SDL reporting the serials set by serial_of().
  SdlInputOptions with_serials(SdlInputOptions options) {
    options.places.serial = [this](int index) { return serials_[SDL_JoystickGetDeviceInstanceID(index)]; };
    return options;
  }
  void serial_of(const VirtualDevice& pad, const std::string& serial) { serials_[pad.instance_id()] = serial; }

  /// The operator's pad, serial OP-1, connects and is lost again: the operator's role is bound to it.
  void bind_the_operator_and_unplug(SdlInput& input, std::optional<VirtualDevice>& operators) {
    ASSERT_TRUE(operators.has_value());
    serial_of(*operators, "OP-1");
    tick(input);
    ASSERT_TRUE(state_.connected());
    operators.reset();
    tick(input);
  }

  static SdlInputOptions by_index() {
    SdlInputOptions options;
    options.controller = "0";
    options.supervisor = "1";
    return options;
  }

  SdlSession session_;
  TickInput tick_;
  InputState& state_ = tick_.state();
  std::int64_t now_ = 0;
  std::map<SDL_JoystickID, std::string> serials_;
};

// SDL's virtual pads have no device path and no serial, as many pads: two
// of one model cannot be told apart, so neither role takes either, and the
// supervisor's pad never drives, before or after both come back in the
// other order (on the old code the operator's role, "controller 0", took the
// supervisor's pad once SDL listed it first).
TEST_F(PadRolesTest, TwoPadsSdlCannotTellApartAreRefusedAndNeverSwap) {
  const andros::testing::LogCapture log;
  std::optional<VirtualDevice> first(twin());
  std::optional<VirtualDevice> second(twin());
  ASSERT_EQ(first->guid(), second->guid());
  SdlInput input(by_index());
  tick(input);
  EXPECT_FALSE(state_.connected());
  EXPECT_FALSE(state_.supervisor().connected());
  EXPECT_NE(log.text().find("error: the operator's controller: refused controller 0 'Twin Pad' (GUID " + first->guid() +
                            ", no device path, no serial): it cannot be told from controller 1 "
                            "'Twin Pad' (GUID " +
                            first->guid() +
                            ", no device path, no serial), so that the roles could swap: use "
                            "controllers of different models, or name each by its port"),
            std::string::npos)
      << log.text();
  first.reset();
  second.reset();
  tick(input);
  second.emplace(twin());  // the supervisor's pad, "controller 1", now listed first
  tick(input);
  second->button(SDL_CONTROLLER_BUTTON_A, true);
  tick(input);
  EXPECT_FALSE(state_.button(kA).down) << "the supervisor's pad drives";
  first.emplace(twin());
  tick(input);
  EXPECT_FALSE(state_.connected());
  EXPECT_FALSE(state_.supervisor().connected());
}

// Issue 33, item 7: through the loop as `run` has it (the flight recorder's
// input around SDL's), a refusal is what the screen's state line says while
// it holds, not "connect a controller" (the log's line scrolls away): both
// pads, then the one left (which may be either), until none is attached.
TEST_F(PadRolesTest, ARefusalIsSaidOnTheStateLineWhileItHolds) {
  const andros::testing::LogCapture log;
  const andros::testing::TempDir dir;
  std::optional<VirtualDevice> first(twin());
  std::optional<VirtualDevice> second(twin());
  SdlInput sdl(by_index());
  record::SessionWriter writer(std::make_unique<record::FileRecordSink>((dir.path() / "run.session").string()));
  record::Recorder recorder(writer);
  record::RecordingInput input(sdl, recorder);
  mapping::Engine frames(mapping::load_mapping(ANDROS_MAPPINGS_DIR "/hd1.yaml"), mapping::EngineOptions{});
  link::SinkLink link([](std::int64_t, const protocol::Frame&) {});
  VirtualClock clock;
  run::Bridge bridge(clock, input, frames, link, run::BridgeOptions{.rate_millihertz = 25'000, .rules = {false, 0x01}});
  view::RunStatusBoard board(view::RunStatus{});
  std::vector<view::RunStatus> seen;
  bridge.run([&] { return seen.size() >= 6; },
             [&](const run::TickReport& r) {
               board.observe(r);
               if (r.shutting_down()) return;
               seen.push_back(board.status());
               if (seen.size() == 2) second.reset();
               if (seen.size() == 4) first.reset();
             });
  writer.close(1000);
  ASSERT_EQ(seen.size(), 6U);
  const std::string twins = "2 identical controllers 'Twin Pad' refused: SDL cannot tell them apart";
  const std::string left = "the operator's controller: 'Twin Pad' refused: SDL cannot tell it from";
  for (std::size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].state, run::OpState::kNoController) << i;
    const auto& said = seen[i].enable_text;
    if (i < 2) EXPECT_EQ(said.rfind(twins, 0), 0U) << i << ": " << said;
    else if (i < 4) EXPECT_EQ(said.rfind(left, 0), 0U) << i << ": " << said;
    else EXPECT_EQ(said, "connect a controller, then press the deadman") << i;
  }
  const auto screen = view::render_run_screen(seen[0], {80, 24}).text();
  EXPECT_NE(screen.find("state       NO CONTROLLER: 2 identical controllers 'Twin Pad' refused"), std::string::npos)
      << screen;
}

// A role that holds its pad keeps it when an identical one appears, but that
// one is refused, and once the first is lost neither is taken: the pad left
// may be either.
TEST_F(PadRolesTest, AModelSeenTwiceStaysRefusedForTheRun) {
  const andros::testing::LogCapture log;
  std::optional<VirtualDevice> operators(twin());
  SdlInput input(by_index());
  tick(input);
  ASSERT_TRUE(state_.connected());
  auto other = twin();
  tick(input);
  EXPECT_TRUE(state_.connected());
  EXPECT_FALSE(state_.supervisor().connected());
  EXPECT_NE(log.text().find("error: the supervisor's controller: refused controller 1 'Twin Pad'"), std::string::npos)
      << log.text();
  operators.reset();
  tick(input);
  other.button(SDL_CONTROLLER_BUTTON_A, true);
  tick(input);
  EXPECT_FALSE(state_.connected()) << "the operator's role took a pad that may be the supervisor's";
  EXPECT_NE(log.text().find("error: the operator's controller: refused controller 0 'Twin Pad' (GUID " + other.guid() +
                            ", no device path, no serial): it cannot be told from controller 0 'Twin Pad'"),
            std::string::npos)
      << log.text();
}

// A pad of the model the other role is bound to, which SDL cannot tell from
// that role's pad (here: no serial), is not taken while that pad is away.
TEST_F(PadRolesTest, APadThatMayBeTheOtherRolesIsRefused) {
  const andros::testing::LogCapture log;
  SdlInputOptions options;
  options.controller = "0";
  options.supervisor = "twin";
  std::optional<VirtualDevice> operators(twin());
  SdlInput input(with_serials(options));
  bind_the_operator_and_unplug(input, operators);
  auto unknown = twin();  // no serial: it may be the operator's pad
  tick(input);
  EXPECT_FALSE(state_.supervisor().connected());
  EXPECT_NE(
      log.text().find("error: the supervisor's controller: refused controller 0 'Twin Pad' (GUID " + unknown.guid() +
                      ", no device path, no serial): it may be the operator's own controller, "
                      "'Twin Pad' (GUID " +
                      unknown.guid() + ", serial OP-1)"),
      std::string::npos)
      << log.text();
}

// Where SDL gives each pad a serial, each role takes back its own pad after
// both were unplugged, whichever comes back first and whatever its index.
TEST_F(PadRolesTest, SerialsKeepEachRoleOnItsOwnPadAcrossAReplugInTheOtherOrder) {
  std::optional<VirtualDevice> operators(twin());
  std::optional<VirtualDevice> supervisors(twin());
  const auto tag = [this](const VirtualDevice& pad, Pad role) {
    serial_of(pad, role == Pad::kOperator ? "OP-1" : "SUP-2");
  };
  tag(*operators, Pad::kOperator);
  tag(*supervisors, Pad::kSupervisor);
  SdlInput input(with_serials(by_index()));
  connect_both(input, *operators, *supervisors);
  replug_in_the_other_order(input, operators, supervisors, tag);
}

// A pad of the same model with another serial is not the role's pad: the
// role waits for its own.
TEST_F(PadRolesTest, ARoleTakesBackOnlyThePadItWasBoundTo) {
  std::optional<VirtualDevice> operators(twin());
  auto supervisors = VirtualDevice::pad("Other Model", 21);
  SdlInput input(with_serials(by_index()));
  bind_the_operator_and_unplug(input, operators);
  auto spare = twin();
  serial_of(spare, "SPARE-3");
  tick(input);
  EXPECT_FALSE(state_.connected()) << "took a spare";
  operators.emplace(twin());
  serial_of(*operators, "OP-1");
  tick(input);
  EXPECT_TRUE(state_.connected());
  EXPECT_TRUE(roles_kept(input, *operators, supervisors));
}

// Two pads that SDL cannot tell apart, each named by its port (a device
// node's link, as /dev/input/by-path/ has): the port is the role's, so a
// replug in the other order keeps the roles.
TEST_F(PadRolesTest, PortsNamedByPathTellIdenticalPadsApart) {
  const andros::testing::TempDir dir;
  std::map<SDL_JoystickID, std::string> nodes;
  const auto node = [&](const VirtualDevice& pad, Pad role) {
    nodes[pad.instance_id()] = dir.write(role == Pad::kOperator ? "event5" : "event6", "").string();
  };
  std::filesystem::create_directory(dir.path() / "by-path");
  std::filesystem::create_symlink(dir.path() / "event5", dir.path() / "by-path" / "usb-port-1");
  std::filesystem::create_symlink(dir.path() / "event6", dir.path() / "by-path" / "usb-port-2");
  SdlInputOptions options;
  options.controller = (dir.path() / "by-path" / "usb-port-1").string();
  options.supervisor = (dir.path() / "by-path" / "usb-port-2").string();
  options.places.path = [&nodes](int index) { return nodes[SDL_JoystickGetDeviceInstanceID(index)]; };
  std::optional<VirtualDevice> operators(twin());
  std::optional<VirtualDevice> supervisors(twin());
  node(*operators, Pad::kOperator);
  node(*supervisors, Pad::kSupervisor);
  SdlInput input(options);
  connect_both(input, *operators, *supervisors);
  replug_in_the_other_order(input, operators, supervisors, node);
}

}  // namespace
}  // namespace andros::input
