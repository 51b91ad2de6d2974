#pragma once
/// A training course's file (docs/trainer.md, "Courses"): YAML, read as
/// strictly as a mapping (every error at its FILE:LINE:COL, unknown keys
/// refused), into the geometry the vehicle model meets (vehicle/course.hpp).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "andros/vehicle/course.hpp"

namespace andros::trainer {

/// A course as it was read: where from, its text (kept whole, as a mapping's
/// is, for the session), and what it says.
struct CourseFile {
  std::string path;  ///< the file read ("" for a recorded text)
  std::string text;
  vehicle::Course course;
};

/// The folders a course NAME is looked for in: `courses/` beside each
/// folder mappings are looked for in (mapping::mapping_search_path()).
std::vector<std::filesystem::path> course_search_path();

/// NAME (a shipped course: `basic`, `car`...: NAME.yaml on the search path)
/// or FILE (a path: it has a `/` or ends in `.yaml`). Throws InputError:
/// at `--course` for a name not found, at FILE:LINE:COL for an error in it.
CourseFile load_course(std::string_view name_or_file);

/// The course text says, read as file's (a recorded course's text too:
/// file is then only a label). Throws InputError (InputErrors for several).
vehicle::Course parse_course(const std::string& file, const std::string& text);

}  // namespace andros::trainer
