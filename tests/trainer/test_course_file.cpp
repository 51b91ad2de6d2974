// A course file with each kind of error is refused at its line and column
// (docs/trainer.md, "Courses"), and every error of a file is said at once.
#include <gtest/gtest.h>

#include "andros/base/error_list.hpp"
#include "andros/trainer/course_file.hpp"

namespace andros::trainer::course_file_test {
namespace {

const std::string kHead = "course: t\nground: {x: [-5, 20], y: [-5, 5]}\nstart: {at: [0, 0]}\n";

/// The first error's `FILE:LINE:COL: error: ...` for text.
std::string error_of(const std::string& text) {
  try {
    (void)parse_course("c.yaml", text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

struct Bad {
  std::string kind;
  std::string text;
  std::string where;  ///< "c.yaml:LINE:COL: error: "
  std::string says;   ///< a part of the message
};

class BadCourse : public ::testing::TestWithParam<Bad> {};

TEST_P(BadCourse, RefusedAtItsLineAndColumn) {
  const auto& b = GetParam();
  const auto what = error_of(b.text);
  EXPECT_EQ(what.rfind(b.where, 0), 0U) << what;
  EXPECT_NE(what.find(b.says), std::string::npos) << what;
}

INSTANTIATE_TEST_SUITE_P(
    Kinds, BadCourse,
    ::testing::Values(
        Bad{"syntax", kHead + "gates: [ {at: [1, 0]\n", "c.yaml:5:1: error: ", "YAML syntax"},
        Bad{"unknown_key", kHead + "gatez: []\n", "c.yaml:4:1: error: ", "unknown key 'gatez' in a course"},
        Bad{"unknown_key_inside", kHead + "gates:\n  - {at: [4, 0], width: 3, hight: 2}\n",
            "c.yaml:5:28: error: ", "unknown key 'hight' in a gate"},
        Bad{"missing_key", "course: t\nstart: {at: [0, 0]}\n", "c.yaml:1:1: error: ", "a course needs 'ground'"},
        Bad{"missing_key_inside", kHead + "boxes:\n  - {at: [3, 3], size: [1, 1]}\n",
            "c.yaml:5:5: error: ", "a box needs 'height'"},
        Bad{"not_a_number", kHead + "time_limit: soon\n", "c.yaml:4:13: error: ", "time_limit 'soon' is not a number"},
        Bad{"out_of_range", kHead + "slopes:\n  - {kind: ramp, at: [5, 0], size: [3, 2], angle: 85}\n",
            "c.yaml:5:51: error: ", "angle 85 is out of range 0..80"},
        Bad{"not_a_list", kHead + "walls: {from: [1, 1], to: [2, 2]}\n", "c.yaml:4:8: error: ", "walls must be a list"},
        Bad{"not_a_point", kHead + "gates:\n  - {at: [4], width: 3}\n",
            "c.yaml:5:10: error: ", "at must be [x, y] in metres"},
        Bad{"bad_kind", kHead + "slopes:\n  - {kind: ladder, at: [5, 0], size: [3, 2], angle: 30}\n",
            "c.yaml:5:12: error: ", "kind must be ramp or stairs, not 'ladder'"},
        Bad{"zero_size", kHead + "boxes:\n  - {at: [3, 3], size: [0, 1], height: 1}\n",
            "c.yaml:5:25: error: ", "length must be above 0"},
        Bad{"ground_backwards", "course: t\nground: {x: [5, -5], y: [-5, 5]}\nstart: {at: [0, 0]}\n",
            "c.yaml:2:13: error: ", "x must be [from, to] with from below to"},
        Bad{"start_off_ground", "course: t\nground: {x: [-5, 5], y: [-5, 5]}\nstart: {at: [9, 0]}\n",
            "c.yaml:3:8: error: ", "the start is off the ground"},
        Bad{"start_in_a_wall", kHead + "walls:\n  - {from: [0, -2], to: [0, 2]}\n",
            "c.yaml:3:8: error: ", "the vehicle would start inside the wall or box at line 5"},
        Bad{"gate_off_ground", kHead + "gates:\n  - {at: [40, 0], width: 3}\n",
            "c.yaml:5:5: error: ", "this gate is off the ground"},
        Bad{"second_document", kHead + "---\ncourse: u\n",
            "c.yaml:5:1: error: ", "a second YAML document ('---'): a course file holds one"},
        Bad{"not_a_map", "- a\n- b\n", "c.yaml:1:1: error: ", "a course file is a map"}),
    [](const auto& p) { return p.param.kind; });

TEST(CourseFile, EveryErrorOfAFileIsSaidAtOnce) {
  try {
    (void)parse_course("c.yaml", kHead + "time_limit: soon\ngates:\n  - {at: [4, 0]}\ntarget: {at: [1, 1], z: x}\n");
    FAIL() << "accepted";
  } catch (const InputErrors& e) {
    ASSERT_EQ(e.errors().size(), 3U) << e.what();
    EXPECT_EQ(e.errors()[0].pos().line, 4);
    EXPECT_EQ(e.errors()[1].pos().line, 6);
    EXPECT_EQ(e.errors()[2].pos().line, 7);
  }
}

TEST(CourseFile, AGoodOneReads) {
  const auto c = parse_course("c.yaml", kHead +
                                            "time_limit: 90\n"
                                            "gates:\n  - {at: [4, 0], heading: 0, width: 3}\n"
                                            "slopes:\n  - {kind: stairs, at: [10, 0], size: [3, 1.2], angle: 35}\n"
                                            "door: {hinge: [15, 1], width: 0.9, closed: -90}\n"
                                            "package: {at: [16, 0], z: 0.5, drop: {at: [2, -3], size: [1, 1]}}\n"
                                            "target: {at: [18, 0], z: 1, radius: 0.2}\n");
  EXPECT_EQ(c.name, "t");
  EXPECT_EQ(c.time_limit_s, 90);
  ASSERT_EQ(c.gates.size(), 1U);
  ASSERT_EQ(c.slopes.size(), 1U);
  EXPECT_TRUE(c.slopes[0].stairs);
  ASSERT_TRUE(c.door && c.package && c.package->drop && c.target);
  EXPECT_EQ(c.door->closed_heading, -90);
  EXPECT_EQ(c.package->z, 0.5);
}

TEST(CourseFile, AShippedCourseNotFoundIsSaidAtTheOption) {
  try {
    (void)load_course("no-such-course");
    FAIL() << "found";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--course: error: no course 'no-such-course'", 0), 0U) << e.what();
  }
}

}  // namespace
}  // namespace andros::trainer::course_file_test
