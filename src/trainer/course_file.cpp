// Reading a course's file (docs/trainer.md, "Courses"), with the mapping
// loader's strict YAML reader: every value checked for type and range, every
// error at its FILE:LINE:COL, all of a file's errors reported together.
#include "andros/trainer/course_file.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <numbers>

#include "../mapping/yaml_reader.hpp"
#include "andros/base/error_list.hpp"
#include "andros/base/text.hpp"
#include "andros/base/text_file.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/vehicle/robot_figures.hpp"

namespace andros::trainer {
namespace {

namespace fs = std::filesystem;
using mapping::yaml::Reader;
using vehicle::Area;
using vehicle::Point;

inline constexpr TextLimits kCourseLimits{"course file", 1 * kMiB, kMaxLineBytes};
/// The largest ground a course may have, either way (metres), and the most of each thing on it.
constexpr double kMaxExtent = 1000;
constexpr std::size_t kMaxItems = 1000;

/// Reads the parts of one course file.
class CourseReader {
 public:
  CourseReader(const Reader& r, vehicle::Course& c) : r_(r), c_(c) {}

  Point point(const YAML::Node& n, std::string_view what) const {
    r_.expect_list(n, what);
    if (n.size() != 2) r_.fail(n, std::string(what) + " must be [x, y] in metres");
    return {r_.number(n[0], -kMaxExtent, kMaxExtent, false, "x"), r_.number(n[1], -kMaxExtent, kMaxExtent, false, "y")};
  }
  double heading(const YAML::Node& map, std::string_view key) const {
    const YAML::Node n = map[std::string(key)];
    return n ? r_.number(n, -360, 360, false, std::string(key)) : 0.0;
  }
  double length(const YAML::Node& n, std::string_view what, double max = kMaxExtent) const {
    if (!n) return 0;
    const double v = r_.number(n, 0, max, false, what);
    if (v == 0) r_.fail(n, std::string(what) + " must be above 0");
    return v;
  }
  /// A map's required key: its node, or an error at the map.
  YAML::Node need(const YAML::Node& map, std::string_view key, std::string_view what) const {
    const YAML::Node n = map[std::string(key)];
    if (!n) r_.fail(map, std::string(what) + " needs '" + std::string(key) + "'");
    return n;
  }
  /// `at: [x, y], size: [length, width], heading: DEG`.
  Area area(const YAML::Node& map, std::string_view what) const {
    const YAML::Node size = need(map, "size", what);
    r_.expect_list(size, "size");
    if (size.size() != 2) r_.fail(size, "size must be [length, width] in metres");
    return {point(need(map, "at", what), "at"), length(size[0], "length"), length(size[1], "width"),
            heading(map, "heading")};
  }
  template <typename Each>
  void list(const YAML::Node& n, std::string_view what, Each each) const {
    r_.expect_list(n, what);
    if (n.size() > kMaxItems) r_.fail(n, "at most " + std::to_string(kMaxItems) + " " + std::string(what));
    for (const auto& item : n) each(item);
  }

  void ground(const YAML::Node& n) const {
    r_.expect_keys(n, {"x", "y"}, "ground");
    const auto range = [&](const YAML::Node& v, std::string_view what, double& lo, double& hi) {
      const Point p = point(v, what);
      if (p.y <= p.x) r_.fail(v, std::string(what) + " must be [from, to] with from below to");
      lo = p.x;
      hi = p.y;
    };
    range(need(n, "x", "ground"), "x", c_.min_x, c_.max_x);
    range(need(n, "y", "ground"), "y", c_.min_y, c_.max_y);
  }
  void start(const YAML::Node& n) const {
    r_.expect_keys(n, {"at", "heading"}, "start");
    c_.start = point(need(n, "at", "start"), "at");
    c_.start_heading = heading(n, "heading");
  }
  void wall(const YAML::Node& n) const {
    r_.expect_keys(n, {"from", "to", "thickness", "height"}, "a wall");
    const Point a = point(need(n, "from", "a wall"), "from");
    const Point b = point(need(n, "to", "a wall"), "to");
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    if (len == 0) r_.fail(n, "a wall's 'from' and 'to' are the same point");
    const double thick = n["thickness"] ? length(n["thickness"], "thickness", 10) : 0.2;
    const double deg = std::atan2(b.y - a.y, b.x - a.x) * 180.0 / std::numbers::pi;
    block_lines_.push_back(r_.pos(n).line);
    c_.blocks.push_back({{{(a.x + b.x) / 2, (a.y + b.y) / 2}, len, thick, deg},
                         n["height"] ? length(n["height"], "height", 100) : 1.0});
  }
  void box(const YAML::Node& n) const {
    r_.expect_keys(n, {"at", "size", "heading", "height"}, "a box");
    block_lines_.push_back(r_.pos(n).line);
    c_.blocks.push_back({area(n, "a box"), length(need(n, "height", "a box"), "height", 100)});
  }
  void slope(const YAML::Node& n) const {
    r_.expect_keys(n, {"kind", "at", "size", "heading", "angle"}, "a slope");
    const auto kind_node = need(n, "kind", "a slope");
    const auto kind = r_.text(kind_node, "kind");
    if (kind != "ramp" && kind != "stairs") r_.fail(kind_node, "kind must be ramp or stairs, not " + quote(kind));
    const double angle = r_.number(need(n, "angle", "a slope"), 0, 80, false, "angle");
    if (angle == 0) r_.fail(n["angle"], "a slope's angle must be above 0 (flat ground needs no slope)");
    c_.slopes.push_back({area(n, "a slope"), angle, kind == "stairs"});
  }
  void landing(const YAML::Node& n) const {
    r_.expect_keys(n, {"at", "size", "heading", "height"}, "a landing");
    c_.landings.push_back({area(n, "a landing"), length(need(n, "height", "a landing"), "height", 100)});
  }
  void door(const YAML::Node& n) const {
    r_.expect_keys(n, {"hinge", "width", "closed", "opens", "handle_height", "height"}, "the door");
    vehicle::Door d;
    d.hinge = point(need(n, "hinge", "the door"), "hinge");
    d.width = length(need(n, "width", "the door"), "width", 10);
    d.closed_heading = heading(n, "closed");
    d.opens = n["opens"] ? r_.number(n["opens"], -180, 180, false, "opens") : 90.0;
    if (d.opens == 0) r_.fail(n["opens"], "a door that opens 0 degrees never opens");
    d.handle_height = n["handle_height"] ? length(n["handle_height"], "handle_height", 10) : 1.0;
    d.height = n["height"] ? length(n["height"], "height", 10) : 2.0;
    c_.door = d;
  }
  void package(const YAML::Node& n) const {
    r_.expect_keys(n, {"at", "z", "size", "mass", "drop"}, "the package");
    vehicle::Package p;
    p.at = point(need(n, "at", "the package"), "at");
    p.z = n["z"] ? r_.number(n["z"], 0, 10, false, "z") : 0.0;
    p.size = n["size"] ? length(n["size"], "size", 2) : 0.3;
    p.mass = n["mass"] ? length(n["mass"], "mass", 100) : 5.0;
    if (n["drop"]) {
      r_.expect_keys(n["drop"], {"at", "size", "heading"}, "the drop area");
      p.drop = area(n["drop"], "the drop area");
    }
    c_.package = p;
  }
  void gate(const YAML::Node& n) const {
    r_.expect_keys(n, {"at", "heading", "width"}, "a gate");
    c_.gates.push_back({point(need(n, "at", "a gate"), "at"), heading(n, "heading"),
                        length(need(n, "width", "a gate"), "width", 100)});
  }
  void finish(const YAML::Node& n) const {
    r_.expect_keys(n, {"at", "size", "heading", "facing", "tolerance"}, "the finish");
    vehicle::Finish f;
    f.area = area(n, "the finish");
    if (n["facing"]) f.heading = r_.number(n["facing"], -360, 360, false, "facing");
    if (n["tolerance"]) f.tolerance = r_.number(n["tolerance"], 0, 180, false, "tolerance");
    c_.finish = f;
  }
  void target(const YAML::Node& n) const {
    r_.expect_keys(n, {"at", "z", "radius"}, "the target");
    c_.target =
        vehicle::Target{point(need(n, "at", "the target"), "at"), n["z"] ? r_.number(n["z"], 0, 100, false, "z") : 1.0,
                        n["radius"] ? length(n["radius"], "radius", 10) : 0.3};
  }

  /// What only the whole course shows: the start and the gates on the ground, the start clear of every block.
  void whole(const YAML::Node& root) const {
    const auto on_ground = [&](Point p) {
      return p.x >= c_.min_x && p.x <= c_.max_x && p.y >= c_.min_y && p.y <= c_.max_y;
    };
    if (!on_ground(c_.start)) r_.fail(root["start"], "the start is off the ground (see 'ground')");
    for (std::size_t i = 0; i < c_.gates.size(); ++i) {
      if (!on_ground(c_.gates[i].at)) r_.fail(root["gates"][i], "this gate is off the ground (see 'ground')");
    }
    const auto& f = vehicle::figures_for("HD1");
    const Area body{c_.start, f.length_m.value, f.width_m.value, c_.start_heading};
    for (std::size_t i = 0; i < c_.blocks.size(); ++i) {
      if (vehicle::overlaps(body, c_.blocks[i].area)) {
        r_.fail(root["start"],
                "the vehicle would start inside the wall or box at line " + std::to_string(block_lines_[i]));
      }
    }
  }

 private:
  const Reader& r_;
  vehicle::Course& c_;
  mutable std::vector<int> block_lines_;  ///< each block's line, for the whole course's errors
};

}  // namespace

vehicle::Course parse_course(const std::string& file, const std::string& text) {
  const Reader r(file, &text, "course");
  std::size_t budget = mapping::yaml::kMaxNodes;
  const YAML::Node root = r.load_document(budget);
  if (!root.IsMap()) r.fail(root, "a course file is a map of 'key: value' lines (docs/trainer.md, \"Courses\")");
  vehicle::Course c;
  CourseReader read(r, c);
  ErrorList errors;
  errors.attempt([&] {
    r.expect_keys(root,
                  {"course", "description", "ground", "start", "time_limit", "walls", "boxes", "slopes", "landings",
                   "door", "package", "gates", "finish", "target"},
                  "a course");
  });
  errors.attempt([&] { c.name = r.text(read.need(root, "course", "a course"), "course"); });
  errors.attempt([&] { read.ground(read.need(root, "ground", "a course")); });
  errors.attempt([&] { read.start(read.need(root, "start", "a course")); });
  errors.attempt([&] {
    if (root["description"]) (void)r.text(root["description"], "description");
  });
  errors.attempt([&] {
    if (root["time_limit"]) c.time_limit_s = r.number(root["time_limit"], 0, 86400, false, "time_limit");
  });
  const auto each = [&](std::string_view key, auto one) {
    const YAML::Node n = root[std::string(key)];
    if (!n) return;
    errors.attempt([&] { read.list(n, key, [&](const YAML::Node& item) { errors.attempt([&] { one(item); }); }); });
  };
  each("walls", [&](const YAML::Node& n) { read.wall(n); });
  each("boxes", [&](const YAML::Node& n) { read.box(n); });
  each("slopes", [&](const YAML::Node& n) { read.slope(n); });
  each("landings", [&](const YAML::Node& n) { read.landing(n); });
  each("gates", [&](const YAML::Node& n) { read.gate(n); });
  const auto one = [&](std::string_view key, auto part) {
    const YAML::Node n = root[std::string(key)];
    if (n) errors.attempt([&] { part(n); });
  };
  one("door", [&](const YAML::Node& n) { read.door(n); });
  one("package", [&](const YAML::Node& n) { read.package(n); });
  one("finish", [&](const YAML::Node& n) { read.finish(n); });
  one("target", [&](const YAML::Node& n) { read.target(n); });
  if (errors.empty()) errors.attempt([&] { read.whole(root); });
  errors.throw_if_any();
  return c;
}

std::vector<fs::path> course_search_path() {
  std::vector<fs::path> dirs;
  for (const auto& d : mapping::mapping_search_path()) dirs.push_back(d.parent_path() / "courses");
  return dirs;
}

CourseFile load_course(std::string_view name_or_file) {
  const std::string arg(name_or_file);
  fs::path path = arg;
  const bool is_file = arg.find('/') != std::string::npos || path.extension() == ".yaml";
  if (!is_file) {
    std::string looked;
    path.clear();
    for (const auto& dir : course_search_path()) {
      std::error_code ec;
      if (fs::is_regular_file(dir / (arg + ".yaml"), ec)) {
        path = dir / (arg + ".yaml");
        break;
      }
      looked += (looked.empty() ? "" : ", ") + dir.string();
    }
    if (path.empty()) {
      throw InputError(SourcePos{"--course"}, "no course " + quote_name(arg) + " (looked for " + printable_text(arg) +
                                                  ".yaml in " + printable_text(looked) + ")");
    }
  }
  CourseFile out;
  out.path = path.string();
  out.text = read_text_file(out.path, kCourseLimits);
  out.course = parse_course(out.path, out.text);
  return out;
}

}  // namespace andros::trainer
