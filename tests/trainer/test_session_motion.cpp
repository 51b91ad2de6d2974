// A session's motion (docs/trainer.md, "Replaying a session"): seeking to a
// time gives, bit for bit, the model that played every tick to it from the
// start, whichever snapshot the seek starts from.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "andros/protocol/frame.hpp"
#include "andros/record/session.hpp"
#include "andros/record/session_replay.hpp"
#include "andros/trainer/stream_hub.hpp"
#include "andros/trainer/trainer_feed.hpp"
#include "andros/trainer/trainer_replay.hpp"
#include "andros/vehicle/robot_figures.hpp"
#include "andros/view/session_motion.hpp"

namespace andros::view {
namespace {

using protocol::ControlState;
using protocol::signal_id;

/// Driving with the given drive and pivot bytes (speed high), the arm's shoulder raised.
protocol::DataBytes driving(std::uint8_t drive, std::uint8_t pivot) {
  ControlState s;
  s[signal_id("safety")] = 1;
  s[signal_id("drive_brake")] = 1;
  s[signal_id("speed_high")] = 1;
  s[signal_id("drive")] = drive;
  s[signal_id("pivot")] = pivot;
  s[signal_id("shoulder_ccw")] = 1;
  s[signal_id("arm_speed")] = 200;
  return protocol::FrameBuilder(0x01).build(s);
}

record::FrameRecord frame(std::int64_t tick, const protocol::DataBytes& data,
                          link::SendResult result = link::SendResult::kSent, std::int64_t gap = 0) {
  record::FrameRecord f;
  f.tick = tick;
  f.t_ms = tick * 40;
  f.data = data;
  f.result = result;
  f.gap = gap;
  return f;
}

/// 2,000 ticks (80 s at 25 Hz): turns, a link down for 3 s (the vehicle's
/// watchdog stops it), ticks skipped by a stall, and a last stretch.
record::Session drive() {
  record::Session s;
  s.settings.robot = "HD1";
  s.settings.rate_millihertz = 25'000;
  s.frames = {frame(0, driving(255, 128)),   frame(300, driving(230, 90)),
              frame(700, driving(200, 170)), frame(900, driving(200, 170), link::SendResult::kDown),
              frame(975, driving(255, 140)), frame(1400, driving(128, 255), link::SendResult::kSent, 30),
              frame(1700, driving(60, 128))};
  s.end = record::EndRecord{.t_ms = 1999 * 40, .last_tick = 1999, .frames_sent = 1900, .why = "", .line = 0};
  return s;
}

/// Every bit of the state that the page and the trail show.
void expect_same_bits(const vehicle::VehicleModel& a, const vehicle::VehicleModel& b, std::int64_t t) {
  const auto bits = [](double v) {
    std::uint64_t u = 0;
    std::memcpy(&u, &v, sizeof u);
    return u;
  };
  const auto& sa = a.state();
  const auto& sb = b.state();
  EXPECT_EQ(bits(sa.pose.x), bits(sb.pose.x)) << "at " << t;
  EXPECT_EQ(bits(sa.pose.y), bits(sb.pose.y)) << "at " << t;
  EXPECT_EQ(bits(sa.pose.heading), bits(sb.pose.heading)) << "at " << t;
  EXPECT_EQ(bits(sa.arm.shoulder), bits(sb.arm.shoulder)) << "at " << t;
  EXPECT_EQ(sa.time_ns, sb.time_ns) << "at " << t;
  EXPECT_EQ(sa.watchdog, sb.watchdog) << "at " << t;
  ASSERT_EQ(a.trail().size(), b.trail().size()) << "at " << t;
  for (std::size_t i = 0; i < a.trail().size(); ++i) {
    ASSERT_EQ(bits(a.trail()[i].x), bits(b.trail()[i].x)) << "at " << t << ", point " << i;
    ASSERT_EQ(bits(a.trail()[i].y), bits(b.trail()[i].y)) << "at " << t << ", point " << i;
  }
}

/// Played from the start: every tick at or before t, in order.
vehicle::VehicleModel played_to(const record::Session& s, std::int64_t t) {
  vehicle::VehicleModel model(vehicle::figures_for(s.settings.robot));
  for_each_tick(s, [&](std::int64_t, std::int64_t t_ms, const record::FrameRecord& f) {
    if (t_ms > t) return false;
    feed_tick(model, t_ms, f.data, f.delivered());
    return true;
  });
  return model;
}

TEST(SessionMotion, SeekingToAnyTimeGivesThePoseOfPlayingToIt) {
  const auto s = drive();
  const SessionMotion motion(s, vehicle::figures_for("HD1"));
  // Before the first snapshot's tick, on ticks, between them, on a snapshot's
  // tick (every 250), in the link's down time, in the skipped ticks, at the end.
  for (const std::int64_t t :
       {-1, 0, 39, 40, 9'999, 10'000, 10'001, 20'020, 36'500, 38'000, 55'000, 56'000, 57'210, 70'000, 79'960, 90'000}) {
    std::int64_t tick = -2;
    const auto seek = motion.at(t, &tick);
    expect_same_bits(seek, played_to(s, t), t);
    if (t >= 0) {
      EXPECT_LE(tick * 40, t);
    }
  }
  expect_same_bits(motion.end(), played_to(s, 80'000), 80'000);
}

TEST(SessionMotion, TheDriveMovesTheVehicleAndTheDownLinksWatchdogStopsIt) {
  const auto s = drive();
  const SessionMotion motion(s, vehicle::figures_for("HD1"));
  const auto& end = motion.end().state();
  EXPECT_GT(std::hypot(end.pose.x, end.pose.y), 20.0);
  EXPECT_GT(end.arm.shoulder, 0.0);
  // From tick 900 the link was down: 500 ms later the vehicle's watchdog stopped it, and it stayed.
  const auto stopped = motion.at(900 * 40 + 600).state();
  const auto later = motion.at(974 * 40).state();
  EXPECT_TRUE(later.watchdog);
  EXPECT_EQ(stopped.pose.x, later.pose.x);
  EXPECT_EQ(stopped.pose.y, later.pose.y);
  // The trail's points carry their times, in order, from the start.
  const auto& trail = motion.trail();
  ASSERT_GT(trail.size(), 100U);
  EXPECT_EQ(trail.front().t_ms, 0);
  for (std::size_t i = 1; i < trail.size(); ++i) ASSERT_LE(trail[i - 1].t_ms, trail[i].t_ms);
  EXPECT_EQ(trail.back().x, motion.end().trail().back().x);
  EXPECT_EQ(motion.length_ms(), 1999 * 40);
}

// Issue 38: a session of a real drive (`run`, the committed sessions of two
// formats) replayed as motion is the trail of the same frames fed live: the
// loop run again on the session's recorded input and mapping, each tick
// handed to the trainer's feed as the live trainer hands it over
// (cmd_trainer: queue_tick after the tick, the motion thread taking them).
TEST(SessionMotion, ARealDrivesSessionReplayedIsTheTrailOfItsFramesFedLive) {
  for (const char* name : {"drive.andros-session", "format3.andros-session"}) {
    SCOPED_TRACE(name);
    const auto checked = record::read_checked_session(std::string(ANDROS_TEST_DATA_DIR "/sessions/") + name);
    ASSERT_TRUE(checked.session);
    ASSERT_TRUE(checked.verdict.intact);
    const auto& session = *checked.session;
    const auto& figures = vehicle::figures_for(session.settings.robot);
    trainer::StreamHub hub;
    trainer::TrainerFeed feed(figures, hub);
    const SessionMotion motion(session, figures);
    EXPECT_GT(motion.trail().size(), 2U);  // it drove
    // At every tick, the pose so far (a frame a tick late or early moves it).
    std::int64_t compared = 0;
    (void)record::replay_session(session, record::load_recorded_mapping, [&](const run::TickReport& r) {
      feed.queue_tick(r.t_ms, r.data, r.delivered());
      feed.take_ticks();
      ASSERT_EQ(feed.summary(), trainer::trail_summary(motion.at(r.t_ms))) << "at " << r.t_ms << " ms";
      ++compared;
    });
    ASSERT_EQ(feed.lost_ticks(), 0U);
    EXPECT_GT(compared, 10);
    EXPECT_EQ(feed.summary(), trainer::trail_summary(motion.end()));
  }
}

}  // namespace
}  // namespace andros::view
