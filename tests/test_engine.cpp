#include <gtest/gtest.h>

#include "andros/engine.hpp"
#include "andros/events.hpp"
#include "andros/mapping_loader.hpp"

namespace andros {
namespace {

using T = InputEvent::Type;

Mapping hd1() { return load_mapping(std::string(ANDROS_MAPPINGS_DIR) + "/hd1.yaml"); }

void apply_script(InputState& s, const std::string& text) {
  for (const auto& e : parse_event_script(text, "t.events")) s.apply(e);
}

TEST(Engine, NeutralUntilFreshDeadmanThenDrives) {
  Engine engine(hd1(), EngineOptions{});
  InputState in;
  auto f = read_signals(engine.step(in, 0));
  EXPECT_EQ(engine.status().enable, EnableState::kNoController);
  EXPECT_EQ(f[signal_id("safety")], 0);
  EXPECT_EQ(f[signal_id("drive")], 128);
  EXPECT_TRUE(validation_errors(engine.step(in, 40)).empty());

  apply_script(in, "80 connect pad\n80 button leftshoulder 1\n80 axis lefty -32768\n");
  f = read_signals(engine.step(in, 80));
  EXPECT_EQ(engine.status().enable, EnableState::kDeadmanNotFresh);
  EXPECT_EQ(f[signal_id("drive")], 128);

  apply_script(in, "90 button leftshoulder 0\n100 button leftshoulder 1\n");
  f = read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().enable, EnableState::kEnabled);
  EXPECT_EQ(f[signal_id("safety")], 1);
  EXPECT_EQ(f[signal_id("drive_brake")], 1);
  EXPECT_EQ(f[signal_id("drive")], 255);  // full forward: 128 + round(1 * 127)
  EXPECT_EQ(f[signal_id("code")], 0x01);

  apply_script(in, "130 disconnect\n");
  f = read_signals(engine.step(in, 160));
  EXPECT_EQ(engine.status().enable, EnableState::kNoController);
  EXPECT_EQ(f[signal_id("drive")], 128);
  EXPECT_EQ(f[signal_id("safety")], 0);
  EXPECT_EQ(read_signals(engine.neutral())[signal_id("drive")], 128);
}

TEST(Engine, PivotContractValue) {
  Mapping m = hd1();
  for (auto& b : m.bindings) {
    if (auto* a = std::get_if<AxisBinding>(&b.rule); a && a->analog == signal_id("pivot")) a->shape = {false, 0.1, 0.5};
  }
  Engine engine(std::move(m), EngineOptions{});
  InputState in;
  engine.step(in, 0);  // start-up: presses before the first tick would not count
  apply_script(in, "0 connect\n10 button leftshoulder 1\n10 axis leftx 16384\n");
  const auto f = read_signals(engine.step(in, 40));
  EXPECT_EQ(f[signal_id("pivot")], 162);
}

}  // namespace
}  // namespace andros
