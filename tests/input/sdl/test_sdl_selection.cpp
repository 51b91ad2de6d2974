// --controller and --controller-db: one device chosen, the others ignored.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>

#include "andros/base/error.hpp"
#include "andros/input/sdl_input.hpp"
#include "support/temp_dir.hpp"
#include "support/virtual_device.hpp"

namespace andros::input {
namespace {

using test::VirtualDevice;

constexpr InputKey kA{InputKind::kPadButton, SDL_CONTROLLER_BUTTON_A};

SdlInputOptions chosen(const std::string& controller, const std::string& controller_db = "") {
  SdlInputOptions o;
  o.controller = controller;
  o.controller_db = controller_db;
  return o;
}

class SdlSelectionTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::use_dummy_video(); }

  void tick(SdlInput& input) { input.pump(tick_, now_ += 40); }

  /// Attaches the two pads and checks that only the one chosen feeds the state.
  void expect_only_beta_counts(const std::function<std::string(const VirtualDevice& beta)>& choose) {
    auto alpha = VirtualDevice::pad("Alpha Pad", 10);
    auto beta = VirtualDevice::pad("Beta Pad", 11);
    SdlInput input(chosen(choose(beta)));
    tick(input);
    ASSERT_TRUE(state_.connected());
    EXPECT_EQ(state_.name(), "Beta Pad");
    alpha.button(SDL_CONTROLLER_BUTTON_A, true);
    tick(input);
    EXPECT_FALSE(state_.button(kA).down) << "alpha mixed in";
    beta.button(SDL_CONTROLLER_BUTTON_A, true);
    tick(input);
    EXPECT_TRUE(state_.button(kA).down);
    beta.unplug();
    tick(input);
    EXPECT_FALSE(state_.connected()) << "fell back to alpha";
  }

  SdlSession session_;
  TickInput tick_;
  InputState& state_ = tick_.state();
  std::int64_t now_ = 0;
};

TEST_F(SdlSelectionTest, ByName) {
  expect_only_beta_counts([](const VirtualDevice&) { return "BETA"; });  // a part, any case
}

TEST_F(SdlSelectionTest, ByGuid) {
  expect_only_beta_counts([](const VirtualDevice& beta) { return beta.guid(); });
}

TEST_F(SdlSelectionTest, ByIndex) {
  expect_only_beta_counts([](const VirtualDevice& beta) { return std::to_string(beta.device_index()); });
}

TEST_F(SdlSelectionTest, DefaultIsTheFirstDevice) {
  if (SDL_NumJoysticks() > 0) GTEST_SKIP() << "a real controller is attached";
  auto alpha = VirtualDevice::pad("Alpha Pad", 10);
  auto beta = VirtualDevice::pad("Beta Pad", 11);
  SdlInput input(SdlInputOptions{});
  tick(input);
  EXPECT_EQ(state_.name(), "Alpha Pad");
}

TEST_F(SdlSelectionTest, NoMatchWaitsAndAMatchingDeviceConnectsLater) {
  auto alpha = VirtualDevice::pad("Alpha Pad", 10);
  SdlInput input(chosen("gamma"));
  tick(input);
  EXPECT_FALSE(state_.connected());
  auto gamma = VirtualDevice::pad("Gamma Pad", 12);
  tick(input);
  EXPECT_TRUE(state_.connected());
  EXPECT_EQ(state_.name(), "Gamma Pad");
}

TEST_F(SdlSelectionTest, ListsEveryDeviceWithItsType) {
  auto pad = VirtualDevice::pad("Alpha Pad", 10);
  auto stick = VirtualDevice::stick("Test Stick");
  SdlInputOptions options;  // SDL's virtual devices have no device node: as a real driver's would be
  options.places.path = [&pad](int index) {
    return SDL_JoystickGetDeviceInstanceID(index) == pad.instance_id() ? "/dev/input/event5" : "";
  };
  const auto list = list_controllers(options);
  const auto find = [&](const std::string& name) {
    return std::find_if(list.begin(), list.end(), [&](const ControllerInfo& c) { return c.name == name; });
  };
  ASSERT_NE(find("Alpha Pad"), list.end());
  ASSERT_NE(find("Test Stick"), list.end());
  EXPECT_TRUE(find("Alpha Pad")->game_controller);
  EXPECT_FALSE(find("Test Stick")->game_controller);
  EXPECT_EQ(find("Alpha Pad")->guid, pad.guid());
  EXPECT_EQ(find("Test Stick")->index, stick.device_index());
  EXPECT_EQ(find("Alpha Pad")->path, "/dev/input/event5");
  EXPECT_EQ(find("Test Stick")->path, "");
}

// --supervisor: a second controller, chosen the same ways, feeding its own pad's state.
class SupervisorSelectionTest : public SdlSelectionTest {
 protected:
  void expect_beta_supervises(const std::function<std::string(const VirtualDevice& beta)>& choose) {
    auto alpha = VirtualDevice::pad("Alpha Pad", 10);
    auto beta = VirtualDevice::pad("Beta Pad", 11);
    SdlInputOptions options;
    options.controller = std::to_string(alpha.device_index());
    options.supervisor = choose(beta);
    SdlInput input(options);
    EXPECT_TRUE(input.supervised());
    tick(input);
    ASSERT_TRUE(state_.connected());
    ASSERT_TRUE(state_.supervisor().connected());
    EXPECT_EQ(state_.name(), "Alpha Pad");
    EXPECT_EQ(state_.supervisor().name(), "Beta Pad");
    beta.button(SDL_CONTROLLER_BUTTON_A, true);
    tick(input);
    EXPECT_TRUE(state_.supervisor().button(kA).down);
    EXPECT_FALSE(state_.button(kA).down) << "the supervisor's press reached the operator's state";
    alpha.button(SDL_CONTROLLER_BUTTON_A, true);
    tick(input);
    EXPECT_TRUE(state_.button(kA).down);
    EXPECT_EQ(state_.supervisor().button(kA).presses, 1U);
    beta.unplug();
    tick(input);
    EXPECT_FALSE(state_.supervisor().connected());
    EXPECT_TRUE(state_.connected()) << "the operator's controller went with the supervisor's";
  }
};

TEST_F(SupervisorSelectionTest, ByIndex) {
  expect_beta_supervises([](const VirtualDevice& beta) { return std::to_string(beta.device_index()); });
}

TEST_F(SupervisorSelectionTest, ByName) {
  expect_beta_supervises([](const VirtualDevice&) { return "beta pad"; });
}

TEST_F(SupervisorSelectionTest, ByGuid) {
  expect_beta_supervises([](const VirtualDevice& beta) { return beta.guid(); });
}

// "The first controller" is the first that is not the supervisor's, and a
// name that matches both devices gives the supervisor the one the operator
// does not hold.
TEST_F(SupervisorSelectionTest, TheOperatorsControllerIsNeverTheSupervisors) {
  if (SDL_NumJoysticks() > 0) GTEST_SKIP() << "a real controller is attached";
  auto alpha = VirtualDevice::pad("Alpha Pad", 10);
  auto beta = VirtualDevice::pad("Beta Pad", 11);
  {
    SdlInputOptions options;
    options.supervisor = "alpha";
    SdlInput input(options);
    tick(input);
    EXPECT_EQ(state_.name(), "Beta Pad");
    EXPECT_EQ(state_.supervisor().name(), "Alpha Pad");
  }
  state_ = InputState{};
  SdlInputOptions options;
  options.controller = "alpha";
  options.supervisor = "pad";  // both match
  SdlInput input(options);
  tick(input);
  EXPECT_EQ(state_.name(), "Alpha Pad");
  EXPECT_EQ(state_.supervisor().name(), "Beta Pad");
  beta.unplug();
  tick(input);
  EXPECT_FALSE(state_.supervisor().connected()) << "the supervisor took the operator's controller";
  EXPECT_TRUE(state_.connected());
}

TEST_F(SupervisorSelectionTest, TheSameChoiceForBothIsRefusedWhereTheSupervisorWasSet) {
  for (const auto& [controller, supervisor] : {std::pair{"1", "1"}, std::pair{"01", "1"}, std::pair{"Xbox", "xbox"}}) {
    SdlInputOptions options;
    options.controller = controller;
    options.supervisor = supervisor;
    options.supervisor_pos = SourcePos{"bridge.conf", 7, 12};
    try {
      SdlInput input(options);
      FAIL() << controller << " and " << supervisor << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.pos().file, "bridge.conf");
      EXPECT_EQ(e.pos().line, 7);
      EXPECT_NE(std::string(e.what()).find("the operator's too (--controller): name another one"), std::string::npos)
          << e.what();
    }
  }
}

TEST(SdlOptions, AnIndexOutOfRangeIsBadInput) {
  test::use_dummy_video();
  EXPECT_THROW(SdlInput(chosen("256")), InputError);
}

class ControllerDbTest : public SdlSelectionTest {
 protected:
  // A directory of this test's own: ctest runs the cases as processes side by
  // side, and a shared file name let one case read another's database.
  std::string write(const std::string& text) { return dir_.write("controller_db.txt", text).string(); }
  testing::TempDir dir_;
  std::string path_ = (dir_.path() / "controller_db.txt").string();
};

TEST_F(ControllerDbTest, AnUnreadableFileIsBadInput) {
  try {
    SdlInput input(chosen("", "/nonexistent/db.txt"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.pos().file, "/nonexistent/db.txt");
  }
}

TEST_F(ControllerDbTest, ABadMappingLineIsBadInputAtItsLine) {
  write("# a comment\n\nnot a mapping at all\n");
  try {
    SdlInput input(chosen("", path_));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.pos().line, 3);
  }
}

TEST_F(ControllerDbTest, AMappingTurnsAPlainJoystickIntoAGameController) {
  auto stick = VirtualDevice::stick("Test Stick");
  write("# other platforms' lines are skipped\n" + stick.guid() +
        ",Mapped Stick,a:b0,b:b1,leftshoulder:b4,leftx:a0,lefty:a1,platform:Windows,\n" + stick.guid() +
        ",Mapped Stick,a:b0,b:b1,leftshoulder:b4,leftx:a0,lefty:a1,platform:Linux,\n");
  SdlInput input(chosen("", path_));
  tick(input);
  EXPECT_EQ(state_.name(), "Mapped Stick");
  stick.button(4, true);
  tick(input);
  EXPECT_TRUE(state_.button(InputKey{InputKind::kPadButton, SDL_CONTROLLER_BUTTON_LEFTSHOULDER}).down);
}

TEST(SdlEnvironment, SdlGameControllerConfigAddsMappings) {
  test::use_dummy_video();
  std::string guid;
  {
    const SdlSession probe;  // the virtual stick's GUID, from its name and ids
    guid = VirtualDevice::stick("Test Stick").guid();
  }
  const std::string mapping = guid + ",Env Stick,a:b0,leftshoulder:b4,leftx:a0,lefty:a1,";
  setenv("SDL_GAMECONTROLLERCONFIG", mapping.c_str(), 1);
  {
    const SdlSession session;  // SDL reads the variable when it starts
    auto stick = VirtualDevice::stick("Test Stick");
    SdlInput input(SdlInputOptions{});
    TickInput tick;
    input.pump(tick, 40);
    EXPECT_EQ(tick.state().name(), "Env Stick");
  }
  unsetenv("SDL_GAMECONTROLLERCONFIG");
}

}  // namespace
}  // namespace andros::input
