// learn end to end, in one process: SDL's virtual pad is the controller (a
// virtual device lives inside the process that made it, so the dialogue runs
// here rather than in a child), a pty is the operator's terminal, and the
// file written is read back by the real loader.
#include <gtest/gtest.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "andros/cli/learn_session.hpp"
#include "andros/mapping/loader.hpp"
#include "support/temp_dir.hpp"
#include "support/virtual_device.hpp"

namespace andros::cli {
namespace {

using test::VirtualDevice;

const std::string kHd1 = std::string(ANDROS_MAPPINGS_DIR) + "/hd1.yaml";

class LearnLive : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::use_dummy_video(); }

  void SetUp() override {
    ASSERT_EQ(openpty(&master_, &slave_, nullptr, nullptr, nullptr), 0);
    ASSERT_EQ(tcgetattr(slave_, &before_), 0);
    out_ = open_memstream(&text_, &size_);
    ASSERT_NE(out_, nullptr);
  }
  void TearDown() override {
    std::fclose(out_);
    std::free(text_);
    close(master_);
    close(slave_);
  }

  /// Steps the session until its output holds `what` after what was already
  /// seen (bounded: a few seconds, never a wall-clock assertion).
  void until(LearnSession& session, const std::string& what) {
    for (int i = 0; i < 1000; ++i) {
      std::fflush(out_);
      const auto at = std::string(text_, size_).find(what, seen_);
      if (at != std::string::npos) {
        seen_ = at + what.size();
        return;
      }
      if (!session.step(5)) break;
    }
    std::fflush(out_);
    FAIL() << "no '" << what << "' after:\n" << std::string(text_, size_).substr(seen_);
  }
  void expect_terminal_restored() const {
    termios after{};
    ASSERT_EQ(tcgetattr(slave_, &after), 0);
    EXPECT_EQ(after.c_lflag, before_.c_lflag);
    EXPECT_EQ(after.c_iflag, before_.c_iflag);
  }
  void type(const char* keys) {
    ASSERT_EQ(write(master_, keys, std::strlen(keys)), static_cast<ssize_t>(std::strlen(keys)));
  }
  /// A push seen by one read of the controller, then the release by the next.
  static void push(VirtualDevice& pad, LearnSession& session, int axis, int value) {
    pad.axis(axis, value);
    session.step(1);
    pad.axis(axis, 0);
  }
  static void press(VirtualDevice& pad, LearnSession& session, int button) {
    pad.button(button, true);
    session.step(1);
    pad.button(button, false);
  }

  input::SdlSession sdl_;
  int master_ = -1;
  int slave_ = -1;
  termios before_{};
  std::FILE* out_ = nullptr;
  char* text_ = nullptr;
  std::size_t size_ = 0;
  std::size_t seen_ = 0;
};

TEST_F(LearnLive, PressesAndKeysMakeAFileTheLoaderReadsBack) {
  testing::TempDir dir;
  const auto output = dir.path() / "mine.yaml";
  auto pad = VirtualDevice::pad("Test Pad");
  pad.button(SDL_CONTROLLER_BUTTON_PADDLE2, true);  // held as the pad appears: never an answer
  input::LiveGestures live({});
  mapping::LearnPlan plan(*mapping::load_mapping(kHd1));
  {
    Keyboard keys(slave_);
    ASSERT_TRUE(keys.terminal());
    termios raw{};
    ASSERT_EQ(tcgetattr(slave_, &raw), 0);
    EXPECT_EQ(raw.c_lflag & (ICANON | ECHO | ISIG), 0U);
    LearnSession session(plan, live, keys, out_);
    until(session, "the deadman: press a button or pull a trigger (Enter keeps leftshoulder)");
    until(session, "  controller: Test Pad\n");
    pad.button(SDL_CONTROLLER_BUTTON_PADDLE2, false);
    pad.axis(SDL_CONTROLLER_AXIS_LEFTX, 9000);  // a stick resting off centre
    for (int i = 0; i < 10; ++i) session.step(1);
    type("\r");
    until(session, "  kept leftshoulder\n");
    until(session,
          "base layer, drive (drive forward/back): push a stick or trigger the way for drive forward and let go "
          "(Enter keeps lefty up)");
    push(pad, session, SDL_CONTROLLER_AXIS_LEFTY, 32767);
    until(session, "  drive: lefty up -> lefty down\n");
    type("\r");  // pivot
    until(session, "pt_left / pt_right (pan left / pan right): push a stick the way for pan left");
    press(pad, session, SDL_CONTROLLER_BUTTON_A);
    until(session, "  refused: pt_left / pt_right takes a stick or trigger, not the button a; try another\n");
    type("\r\r");  // pan, tilt
    until(session, "base layer, front_art_up (front articulators up): press a button");
    press(pad, session, SDL_CONTROLLER_BUTTON_B);
    until(session, "  refused: 'b' is already used for selector inset_video next in the base layer; try another\n");
    press(pad, session, SDL_CONTROLLER_BUTTON_PADDLE1);
    until(session, "  front_art_up: dpup -> paddle1\n");
    type("b");  // back: the step shows what was just chosen
    until(session,
          "[6/61] base layer, front_art_up (front articulators up): press a button, or push a stick or "
          "trigger the way that sets it and let go (Enter keeps paddle1)\n");
    type("\r");
    until(session, "  kept paddle1\n");
    type("s");
    until(session, "layer 'arm', the key of layer 'arm' (toggle): press a button (Enter keeps rightstick)");
    type("w");
    while (session.step(5)) {
    }
    EXPECT_EQ(session.end(), LearnSession::End::kWrite);
  }
  expect_terminal_restored();

  write_learned(plan, plan.extending_yaml(extends_name(kHd1, "HD1", output), plan.base()), output);
  const auto loaded = *mapping::load_mapping(output);
  EXPECT_TRUE(plan.matches(loaded));
  std::stringstream text;
  text << std::ifstream(output).rdbuf();
  EXPECT_NE(text.str().find("  - signal: front_art_up    # was dpup\n    button: paddle1\n"), std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("  - analog: drive    # was lefty\n    axis: lefty\n"), std::string::npos) << text.str();
  EXPECT_EQ(plan.learned().bindings.size(), loaded.bindings.size());
  const auto check = std::string(ANDROS_BIN) + " check '" + output.string() + "' >/dev/null 2>&1";
  EXPECT_EQ(std::system(check.c_str()), 0) << check;
}

TEST_F(LearnLive, CtrlCQuitsAndRestoresTheTerminal) {
  auto pad = VirtualDevice::pad("Test Pad");
  input::LiveGestures live({});
  mapping::LearnPlan plan(*mapping::load_mapping(kHd1));
  {
    Keyboard keys(slave_);
    LearnSession session(plan, live, keys, out_);
    until(session, "[1/");
    press(pad, session, SDL_CONTROLLER_BUTTON_PADDLE3);
    until(session, "  the deadman: leftshoulder -> paddle3\n");
    type("\x03");
    while (session.step(5)) {
    }
    EXPECT_EQ(session.end(), LearnSession::End::kQuit);
  }
  expect_terminal_restored();
}

}  // namespace
}  // namespace andros::cli
