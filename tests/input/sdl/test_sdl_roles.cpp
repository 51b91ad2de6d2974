// Roles that cannot swap: the operator's and the supervisor's controllers are
// two physical pads, whatever order SDL lists them in after a replug.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "andros/input/sdl_input.hpp"
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

  void tick(SdlInput& input) { input.pump(state_, now_ += 40); }

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

  static SdlInputOptions by_index() {
    SdlInputOptions options;
    options.controller = "0";
    options.supervisor = "1";
    return options;
  }

  SdlSession session_;
  InputState state_;
  std::int64_t now_ = 0;
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

// Where SDL gives each pad a serial, each role takes back its own pad after
// both were unplugged, whichever comes back first and whatever its index.
TEST_F(PadRolesTest, SerialsKeepEachRoleOnItsOwnPadAcrossAReplugInTheOtherOrder) {
  std::map<SDL_JoystickID, std::string> serials;
  auto options = by_index();
  options.places.serial = [&serials](int index) { return serials[SDL_JoystickGetDeviceInstanceID(index)]; };
  std::optional<VirtualDevice> operators(twin());
  std::optional<VirtualDevice> supervisors(twin());
  serials[operators->instance_id()] = "OP-1";
  serials[supervisors->instance_id()] = "SUP-2";
  SdlInput input(options);
  tick(input);
  ASSERT_TRUE(state_.connected());
  ASSERT_TRUE(state_.supervisor().connected());
  EXPECT_TRUE(roles_kept(input, *operators, *supervisors));
  operators.reset();
  supervisors.reset();
  tick(input);
  supervisors.emplace(twin());  // now controller 0: what --controller named
  serials[supervisors->instance_id()] = "SUP-2";
  tick(input);
  EXPECT_FALSE(state_.connected()) << "the operator's role took the supervisor's pad";
  EXPECT_TRUE(state_.supervisor().connected());
  operators.emplace(twin());
  serials[operators->instance_id()] = "OP-1";
  tick(input);
  ASSERT_TRUE(state_.connected());
  EXPECT_TRUE(roles_kept(input, *operators, *supervisors));
}

// A pad of the same model with another serial is not the role's pad: the
// role waits for its own.
TEST_F(PadRolesTest, ARoleTakesBackOnlyThePadItWasBoundTo) {
  std::map<SDL_JoystickID, std::string> serials;
  auto options = by_index();
  options.places.serial = [&serials](int index) { return serials[SDL_JoystickGetDeviceInstanceID(index)]; };
  std::optional<VirtualDevice> operators(twin());
  auto supervisors = VirtualDevice::pad("Other Model", 21);
  serials[operators->instance_id()] = "OP-1";
  SdlInput input(options);
  tick(input);
  ASSERT_TRUE(state_.connected());
  operators.reset();
  tick(input);
  auto spare = twin();
  serials[spare.instance_id()] = "SPARE-3";
  tick(input);
  EXPECT_FALSE(state_.connected()) << "took a spare";
  operators.emplace(twin());
  serials[operators->instance_id()] = "OP-1";
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
  const auto node = [&](const VirtualDevice& pad, const std::string& name) {
    nodes[pad.instance_id()] = dir.write(name, "").string();
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
  node(*operators, "event5");
  node(*supervisors, "event6");
  SdlInput input(options);
  tick(input);
  ASSERT_TRUE(state_.connected());
  ASSERT_TRUE(state_.supervisor().connected());
  EXPECT_TRUE(roles_kept(input, *operators, *supervisors));
  operators.reset();
  supervisors.reset();
  tick(input);
  supervisors.emplace(twin());  // listed first now
  node(*supervisors, "event6");
  tick(input);
  EXPECT_FALSE(state_.connected()) << "the operator's port took the supervisor's pad";
  operators.emplace(twin());
  node(*operators, "event5");
  tick(input);
  ASSERT_TRUE(state_.connected());
  ASSERT_TRUE(state_.supervisor().connected());
  EXPECT_TRUE(roles_kept(input, *operators, *supervisors));
}

}  // namespace
}  // namespace andros::input
