// Each shipped course (courses/) completed by its shipped script with the
// shipped mapping: the script through the real mapping and the run loop on
// the virtual clock (replay), each tick's report into the course's scorer.
// A change to a course, a script, the model or the mapping that makes a
// course impossible (or no longer completed by its script) fails here.
#include <gtest/gtest.h>

#include "andros/base/text_file.hpp"
#include "andros/input/script_player.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/run/replay.hpp"
#include "andros/trainer/course_file.hpp"
#include "andros/trainer/course_score.hpp"
#include "support/replay_data.hpp"

namespace andros::trainer::courses_test {
namespace {

const std::string kCourses = ANDROS_COURSES_DIR "/";

struct Shipped {
  std::string name;
  std::string mapping;  ///< under mappings/
  bool weapons = false;
};

/// A script through replay with the course's mapping, scored.
Score play(const Shipped& c, const vehicle::Course& course, const std::string& events) {
  const mapping::EngineOptions options{.weapons = c.weapons, .code = 0x01};
  mapping::Engine engine(mapping::load_mapping(ANDROS_MAPPINGS_DIR "/" + c.mapping), options);
  TextReader in(testing::read_text(events), events, kEventScriptLimits);
  input::ScriptPlayer player(in);
  CourseScorer scorer(vehicle::figures_for("HD1"), course);
  run::ReplayOptions replay_options{.engine = options};
  replay_options.observe = [&](const run::TickReport& r) { scorer.on_tick(r); };
  run::replay(player, std::move(engine), replay_options, [](std::int64_t, const protocol::DataBytes&) {});
  return scorer.score();
}

class ShippedCourse : public ::testing::TestWithParam<Shipped> {};

TEST_P(ShippedCourse, ItsScriptCompletesIt) {
  const auto& c = GetParam();
  const auto file = load_course(kCourses + c.name + ".yaml");
  EXPECT_EQ(file.course.name, c.name);
  const auto score = play(c, file.course, kCourses + c.name + ".events");
  EXPECT_TRUE(score.completed) << score_text(score);
  EXPECT_EQ(score.gates, score.gates_total);
  EXPECT_EQ(score.contacts, 0U) << score_text(score);
  EXPECT_FALSE(score.tipped);
  EXPECT_TRUE(score.stops.empty()) << score_text(score);
  EXPECT_EQ(score.fired_off_target, 0U);
  // The course's name finds the same file (a shipped course by its name).
  EXPECT_EQ(load_course(c.name).text, file.text);
}

INSTANTIATE_TEST_SUITE_P(Courses, ShippedCourse,
                         ::testing::Values(Shipped{"basic", "hd1.yaml"}, Shipped{"stairs", "hd1.yaml"},
                                           Shipped{"car", "hd1.yaml"},
                                           Shipped{"weapons", "examples/supervisor.yaml", true}),
                         [](const auto& p) { return p.param.name; });

const std::string kData = ANDROS_TEST_DATA_DIR "/trainer/";

TEST(CourseScore, ContactsStopsAndInputsNotAtRestAreCounted) {
  // Enabled with the stick held, into the bay's back wall, the operator's stop.
  const Shipped basic{"basic", "hd1.yaml"};
  const auto course = load_course(kCourses + "basic.yaml").course;
  const auto score = play(basic, course, kData + "course_bump.events");
  EXPECT_FALSE(score.completed);
  EXPECT_EQ(score.result, "not finished: not in the finish");
  EXPECT_EQ(score.contacts, 1U);
  EXPECT_EQ(score.not_at_rest, 1U);
  ASSERT_EQ(score.stops.size(), 1U);
  EXPECT_EQ(score.stops[0].by, "operator");
  EXPECT_EQ(score.stops[0].why, "stop button");
  EXPECT_EQ(score.stops[0].t_ms, 8000);
  // The same ticks, the same score.
  EXPECT_EQ(score_json(play(basic, course, kData + "course_bump.events")), score_json(score));
}

TEST(CourseScore, WeaponDisciplineIsCounted) {
  // A shot under consent with the laser off the target; a fire press without consent.
  const Shipped weapons{"weapons", "examples/supervisor.yaml", true};
  const auto score =
      play(weapons, load_course(kCourses + "weapons.yaml").course, kData + "weapons_undisciplined.events");
  EXPECT_EQ(score.fired, 1U) << score_text(score);
  EXPECT_EQ(score.fired_off_target, 1U);
  EXPECT_EQ(score.hits, 0U);
  EXPECT_EQ(score.fire_refused, 1U);
  EXPECT_FALSE(score.completed);
}

}  // namespace
}  // namespace andros::trainer::courses_test
