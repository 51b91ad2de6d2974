#include <gtest/gtest.h>

#include <sstream>

#include "andros/cli/config.hpp"
#include "support/input_error.hpp"

namespace andros::cli {
namespace {

Settings parse(const std::string& text, const std::string& file = "dir/test.conf") {
  Settings c;
  TextReader in(text, file, kConfigLimits);
  parse_config(in, c);
  return c;
}

std::string error_of(const std::string& text) {
  return testing::input_error_text([&] { parse(text); });
}

// The defaults docs/running.md gives (the configuration file and the flags).
TEST(Config, DefaultsAreTheDocumentedOnes) {
  const Settings c;
  EXPECT_EQ(c.robot, "HD1");
  EXPECT_EQ(c.port, "sim");
  EXPECT_EQ(c.baud, 9600);
  EXPECT_EQ(c.code, 0x01);
  EXPECT_EQ(c.rate.millihertz, 25'000);
  EXPECT_FALSE(c.weapons);
  EXPECT_EQ(c.input, "sdl");
}

TEST(Config, ReadsTheLegacyFileAsIs) {
  const auto c = parse(
      "#This is the configuration file for the packet generator\n"
      "# Baud rate setting: 9600, 19200, 38400, 57600, 115200\n"
      "baudrate=19200\n"
      "# Serial port\n"
      "serialport=/dev/ttyUSB0\n"
      "# Robot type: F6A, VA1, WOLVERINE, HD1, PROWLER, RAV, RONS\n"
      "robot=wolverine\n"
      "# Control code: 8 bit hex value according to the dip switches in the switchbox\n"
      "code=3C\n");
  EXPECT_EQ(c.baud, 19200);
  EXPECT_EQ(c.port, "/dev/ttyUSB0");
  EXPECT_EQ(c.robot, "WOLVERINE");
  EXPECT_EQ(c.code, 0x3C);
}

TEST(Config, ReadsTheBridgesOwnKeys) {
  const auto c = parse(" rate = 20 \r\nweapons=enabled\nmapping=custom.yaml\ninput=demo.events\n\n");
  EXPECT_EQ(c.rate.millihertz, 20'000);
  EXPECT_EQ(c.rate.text, "20");
  EXPECT_EQ(c.rate.pos.line, 1);
  EXPECT_TRUE(c.weapons);
  EXPECT_EQ(c.mapping, "dir/custom.yaml");  // relative to the file
  EXPECT_EQ(c.input, "dir/demo.events");
  EXPECT_EQ(parse("input=sdl\nmapping=/abs/m.yaml\n").input, "sdl");
  EXPECT_EQ(parse("mapping=/abs/m.yaml\n").mapping, "/abs/m.yaml");
}

TEST(Config, TheSupervisorsControllerIsKeptWithWhereItWasSet) {
  const auto c = parse("robot=HD1\nsupervisor = Pad B\n");
  EXPECT_EQ(c.supervisor, "Pad B");
  EXPECT_EQ(c.supervisor_pos.line, 2);
  EXPECT_EQ(c.supervisor_pos.column, 14);
  EXPECT_EQ(parse("robot=HD1\n").supervisor, "");  // none by default
}

TEST(Config, BadLinesNameFileAndLine) {
  EXPECT_EQ(error_of("# c\nbaudrate=9601\n"),
            "dir/test.conf:2:10: error: baud 9601 is not one of 9600, 19200, 38400, 57600, 115200");
  EXPECT_EQ(error_of("speed=3\n"),
            "dir/test.conf:1:1: error: unknown key 'speed' (known: baudrate, serialport, robot, code, "
            "rate, mapping, weapons, input, supervisor, record, record_dir, record_max_mb, record_max_days)");
  EXPECT_NE(error_of("\n\nrobot=R2D2\n").find("dir/test.conf:3:7: error: unknown robot 'R2D2'"), std::string::npos);
  EXPECT_EQ(error_of("supervisor = 256\n"), "dir/test.conf:1:14: error: controller index 256 is out of range 0..255");
  EXPECT_NE(error_of("code=XYZ\n").find("dir/test.conf:1:6: error: code 'XYZ'"), std::string::npos);
  EXPECT_NE(error_of("just words\n").find("dir/test.conf:1:1: error: expected key=value"), std::string::npos);
  EXPECT_NE(error_of("serialport=\n").find("dir/test.conf:1: error: 'serialport' has no value"), std::string::npos);
  EXPECT_NE(error_of("weapons=maybe\n").find("dir/test.conf:1:9: error: weapons"), std::string::npos);
  EXPECT_NE(error_of("rate=0\n").find("dir/test.conf:1:6: error: rate '0' is below 1 Hz"), std::string::npos);
  EXPECT_NE(error_of("rate=fast\n").find("dir/test.conf:1:6: error: rate 'fast' is not a number"), std::string::npos);
}

TEST(Config, AKeyGivenTwiceIsAnErrorAtTheSecondNamingTheFirst) {
  // Never "last wins": a weapons=enabled far below a weapons=disabled would arm the run unseen.
  EXPECT_EQ(error_of("weapons=disabled\n# later\nrobot=hd1\n  weapons = enabled\n"),
            "dir/test.conf:4:3: error: key 'weapons' given twice (first at line 1)");
  // Keys are case-insensitive, so are their repeats; the same value twice is still twice.
  EXPECT_EQ(error_of("\nRobot=HD1\nROBOT=hd1\n"),
            "dir/test.conf:3:1: error: key 'robot' given twice (first at line 2)");
}

TEST(Config, RefusesARateThatCannotFitWhereItWasSet) {
  auto c = parse("rate=12.5\n");
  EXPECT_EQ(c.rate.millihertz, 12'500);
  c = parse("# fast\nrate=30\nbaudrate=19200\n");
  EXPECT_NO_THROW(timing::check_rate_fits(c.rate, c.baud));
  EXPECT_EQ(c.rate.millihertz, 30'000);
  c.baud = 9600;  // a --baud flag over the file
  try {
    timing::check_rate_fits(c.rate, c.baud);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "dir/test.conf:2:6: error: rate '30' does not fit the link: 360-bit frames at 9600 baud "
                 "allow at most 26.666 Hz");
  }
}

TEST(Config, DefaultPathsPreferXdg) {
  setenv("XDG_CONFIG_HOME", "/x", 1);
  const auto paths = default_config_paths();
  ASSERT_EQ(paths.size(), 2u);
  EXPECT_EQ(paths[0], "/x/andros-bridge/andros-bridge.conf");
  EXPECT_EQ(paths[1], "/etc/andros-bridge/andros-bridge.conf");
  unsetenv("XDG_CONFIG_HOME");
}

}  // namespace
}  // namespace andros::cli
