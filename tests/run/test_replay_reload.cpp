// One answer to a reload that fails (run/replay.hpp): whatever the reading
// throws, replay keeps the old mapping, says so and goes on, as `run` does.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/input/script_player.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/signals.hpp"
#include "andros/run/replay.hpp"

namespace andros::run {
namespace {

const std::string kHd1 = ANDROS_MAPPINGS_DIR "/hd1.yaml";

TEST(ReplayReload, AReloadThatCannotBeReadKeepsTheOldMappingAndGoesOn) {
  TextReader in("0 connect pad\n40 reload unreadable.yaml\n200 button leftshoulder 1\n240 axis lefty -32768\n400 end\n",
                "s.events", kEventScriptLimits);
  input::ScriptPlayer player(in);
  ReplayOptions options;
  options.load = [](const std::string& file) -> mapping::ValidMapping {
    throw RuntimeError(file + ": cannot read: Input/output error");
  };
  std::vector<std::pair<std::int64_t, ReloadOutcome>> outcomes;
  options.reloaded = [&](std::int64_t t, const ReloadOutcome& o) { outcomes.emplace_back(t, o); };
  std::vector<std::pair<std::int64_t, protocol::DataBytes>> frames;
  EXPECT_NO_THROW(replay(player, mapping::Engine(mapping::load_mapping(kHd1), options.engine), options,
                         [&](std::int64_t t, const protocol::DataBytes& d) { frames.emplace_back(t, d); }));
  ASSERT_EQ(outcomes.size(), 1u);
  EXPECT_FALSE(outcomes[0].second.ok);
  EXPECT_EQ(outcomes[0].second.message, "unreadable.yaml: cannot read: Input/output error");
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames.back().first, 400);  // on to the script's end
  // The old mapping drives after a fresh press, as after any reload.
  EXPECT_EQ(protocol::read_signals(frames.back().second)[protocol::signal_id("drive")], 255);
}

}  // namespace
}  // namespace andros::run
