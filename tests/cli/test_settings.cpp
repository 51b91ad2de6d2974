#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "andros/cli/command_line.hpp"
#include "andros/cli/config.hpp"
#include "support/input_error.hpp"
#include "support/temp_dir.hpp"

namespace andros::cli {
namespace {

/// A command's flags on an app of its own, parsed from a command line.
struct Parsed {
  CLI::App app;
  CommandLine flags;
  Parsed(Command command, const std::string& args) : flags(app, command) { app.parse(args, false); }
};

Settings from_flags(Command command, const std::string& args) {
  Parsed p(command, args);
  return resolve_settings(p.flags);
}

Settings from_file(const std::string& text) {
  Settings s;
  TextReader in(text, "/etc/test.conf", kConfigLimits);
  parse_config(in, s);
  return s;
}

using testing::input_error_text;

/// A value for every row other than its default, as a user would write it.
std::string sample(const Setting& row) {
  const auto flag = flag_name(row);
  if (flag == "--rate" && row.commands == kRecord) return "50";
  if (flag == "--baud") return "57600";
  if (flag == "--port") return "/dev/ttyUSB3";
  if (flag == "--robot") return "rav";
  if (flag == "--code") return "3c";
  if (flag == "--rate") return "12.5";
  if (flag == "--weapons") return "enabled";
  if (flag == "--format") return "jsonl";
  if (flag == "--supervisor") return "2";
  if (flag == "--no-record") return "disabled";
  if (flag == "--record-max-mb") return "20";
  if (flag == "--record-max-days") return "7";
  return "/abs/file";  // --config, --mapping, --input, --output
}

TEST(Settings, EveryKeyedRowReadsTheSameFromTheFileAndTheFlag) {
  int keyed = 0;
  for (const auto& row : settings_table()) {
    if (row.key.empty()) continue;
    ++keyed;
    const auto flag = std::string(flag_name(row));
    const auto text = sample(row);
    const auto file = from_file(std::string(row.key) + " = " + text + "\n");
    const auto cli = from_flags(kRun, row.value_name.empty() ? flag : flag + " " + text);
    EXPECT_EQ(row.show(file), row.show(cli)) << row.key;
    EXPECT_NE(row.show(file), row.show(Settings{})) << row.key << ": the sample is the default";
  }
  EXPECT_EQ(keyed, 13);  // the legacy four and rate, mapping, weapons, input, supervisor; the recorder's four
}

TEST(Settings, EveryRowTakesBackWhatItShows) {
  for (const auto& row : settings_table()) {
    const auto flag = std::string(flag_name(row));
    for (const auto& text : {sample(row), row.show(Settings{})}) {
      if (text.empty()) continue;
      Settings once;
      row.parse(text, SourcePos{flag}, once);
      Settings twice;
      row.parse(row.show(once), SourcePos{flag}, twice);
      EXPECT_EQ(row.show(twice), row.show(once)) << flag << " " << text;
    }
  }
}

TEST(Settings, TheRateIsParsedOnceIntoMillihertz) {
  const auto s = from_flags(kReplay, "--rate 12.5");
  EXPECT_EQ(s.rate.millihertz, 12'500);
  EXPECT_EQ(s.rate.pos.file, "--rate");
  EXPECT_EQ(Settings{}.rate.millihertz, timing::kDefaultRateMillihertz);
}

TEST(Settings, FlagsBeatTheFileWhichBeatsTheDefaults) {
  const testing::TempDir dir;
  const auto conf = dir.write("a.conf", "baudrate=19200\ncode=3C\nrobot=rav\nmapping=m.yaml\nrate=20\n").string();
  auto s = from_flags(kRun, "--config " + conf + " --code 5A");
  EXPECT_EQ(s.baud, 19200);                                // the file
  EXPECT_EQ(s.code, 0x5A);                                 // the flag over the file
  EXPECT_EQ(s.mapping, (dir.path() / "m.yaml").string());  // relative to the file
  EXPECT_EQ(s.port, "sim");                                // the default
  EXPECT_EQ(s.rate.pos.line, 5);
  // A robot on the command line drops the file's mapping; a mapping flag stays.
  EXPECT_EQ(from_flags(kRun, "--config " + conf + " --robot hd1").mapping, "");
  EXPECT_EQ(from_flags(kRun, "--config " + conf + " --robot hd1 --mapping x.yaml").mapping, "x.yaml");
}

TEST(Settings, TheRateIsCheckedAgainstTheFinalBaudWhereItWasSet) {
  const testing::TempDir dir;
  const auto conf = dir.write("fast.conf", "rate=30\nbaudrate=19200\n").string();
  EXPECT_EQ(from_flags(kRun, "--config " + conf).rate.millihertz, 30'000);
  EXPECT_EQ(input_error_text([&] { from_flags(kRun, "--config " + conf + " --baud 9600"); }),
            conf + ":1:6: error: rate '30' does not fit the link: 360-bit frames at 9600 baud allow at most 26.666 Hz");
  EXPECT_EQ(input_error_text([&] { from_flags(kReplay, "--rate 30"); }),
            "--rate: error: rate '30' does not fit the link: 360-bit frames at 9600 baud allow at most 26.666 Hz");
}

TEST(Settings, OnlyRunReadsAConfigFile) {
  const testing::TempDir dir;
  std::filesystem::create_directories(dir.path() / "andros-bridge");
  dir.write("andros-bridge/andros-bridge.conf", "code=3C\n");
  setenv("XDG_CONFIG_HOME", dir.path().c_str(), 1);
  EXPECT_EQ(from_flags(kRun, "").code, 0x3C);
  EXPECT_EQ(from_flags(kReplay, "").code, kDefaultCode);
  unsetenv("XDG_CONFIG_HOME");
}

TEST(Settings, BadFlagValuesNameTheFlag) {
  EXPECT_EQ(input_error_text([] { from_flags(kMonitor, "--baud 1234"); }),
            "--baud: error: baud 1234 is not one of 9600, 19200, 38400, 57600, 115200");
  EXPECT_EQ(input_error_text([] { from_flags(kReplay, "--robot hd9"); }),
            "--robot: error: unknown robot 'hd9' (one of F6A, VA1, WOLVERINE, HD1, PROWLER, RAV, RONS)");
  EXPECT_EQ(input_error_text([] { from_flags(kRecord, "--rate 0"); }), "--rate: error: rate 0 is out of range 1..1000");
  EXPECT_EQ(input_error_text([] { from_flags(kReplay, "--format csv"); }),
            "--format: error: format 'csv' is not one of hex, raw, jsonl");
}

TEST(Settings, EachCommandTakesItsRowsOnly) {
  EXPECT_EQ(from_flags(kMonitor, "--code 3C").expected_code, 0x3C);
  EXPECT_FALSE(from_flags(kMonitor, "").expected_code);
  EXPECT_EQ(from_flags(kRecord, "-o x.events --rate 50").script_output, "x.events");
  EXPECT_EQ(from_flags(kRecord, "--rate 50").read_rate_hz, 50);
  EXPECT_THROW(from_flags(kMonitor, "--robot hd1"), CLI::ParseError);
  EXPECT_THROW(from_flags(kReplay, "--port sim"), CLI::ParseError);
}

TEST(Settings, HelpListsFromTheTables) {
  const auto help = [](std::string_view flag, Command c) { return help_text(*find_flag(flag, c)); };
  for (const auto robot : protocol::kRobotTypes) EXPECT_NE(help("--robot", kRun).find(robot), std::string::npos);
  for (const int baud : kBauds) EXPECT_NE(help("--baud", kRun).find(std::to_string(baud)), std::string::npos);
  EXPECT_NE(help("--rate", kReplay).find("at most 26.666 Hz at 9600 baud"), std::string::npos);
  EXPECT_EQ(default_text(*find_flag("--robot", kRun)), protocol::kDefaultRobot);
  EXPECT_EQ(default_text(*find_flag("--rate", kRun)), "25");
  EXPECT_EQ(default_text(*find_flag("--baud", kMonitor)), "9600");
  EXPECT_EQ(default_text(*find_flag("--code", kRun)), "01");
}

}  // namespace
}  // namespace andros::cli
