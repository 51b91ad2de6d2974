// A committed drive script, through the real mapping and the run loop on the
// virtual clock (replay), into the vehicle model frame by frame as the wire
// carries them: its trail must match the committed digest. A change to the
// model, the mapping or the loop that moves the vehicle otherwise shows here.
#include <gtest/gtest.h>

#include <cstdio>

#include "andros/base/sha256.hpp"
#include "andros/base/text_file.hpp"
#include "andros/input/script_player.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/decoder.hpp"
#include "andros/run/replay.hpp"
#include "andros/vehicle/vehicle_model.hpp"
#include "support/replay_data.hpp"

namespace andros::vehicle {
namespace {

const std::string kDir = ANDROS_TEST_DATA_DIR "/trainer/";

/// The trail as text: a point a line, millimetres.
std::string trail_text(const VehicleModel& model) {
  std::string out;
  char line[64];
  for (const auto& p : model.trail()) {
    std::snprintf(line, sizeof line, "%.3f %.3f\n", p.x, p.y);
    out += line;
  }
  const auto& end = model.state().pose;
  std::snprintf(line, sizeof line, "end %.3f %.3f %.2f\n", end.x, end.y, end.heading);
  return out + line;
}

TEST(TrainerTrail, TheCommittedDriveGivesTheCommittedTrail) {
  const std::string events = kDir + "drive_course.events";
  const mapping::EngineOptions options{.weapons = false, .code = 0x01};
  mapping::Engine engine(mapping::load_mapping(ANDROS_MAPPINGS_DIR "/hd1.yaml"), options);
  TextReader in(testing::read_text(events), events, kEventScriptLimits);
  input::ScriptPlayer player(in);
  VehicleModel model(figures_for("HD1"));
  protocol::Decoder decoder(0x01);
  run::ReplayOptions replay_options{.engine = options};
  replay_options.wire = [&](std::int64_t t_ms, const protocol::Frame& frame) {
    decoder.push(frame, [&](const protocol::DecodedFrame& f) { model.on_frame(f, t_ms * 1'000'000); });
  };
  run::replay(player, std::move(engine), replay_options, [](std::int64_t, const protocol::DataBytes&) {});

  const auto text = trail_text(model);
  const auto want = testing::read_text(kDir + "drive_course.trail");
  const auto got = sha256_hex(text) + "\n";
  EXPECT_EQ(got, want) << "the trail now (write its digest to drive_course.trail if the change is meant):\n" << text;
  // What the drive says, whatever the digest: forward, then left of the start line, flippers up, stopped.
  const auto& s = model.state();
  EXPECT_GT(s.pose.x, 5.0);
  EXPECT_GT(s.pose.y, 1.0);
  EXPECT_GT(s.front_flipper, 0.0);
  EXPECT_EQ(s.speed, 0.0);
  EXPECT_EQ(s.ignored, 0U);
}

}  // namespace
}  // namespace andros::vehicle
