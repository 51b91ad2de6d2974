#include "andros/trainer/course_view.hpp"

#include <cmath>

namespace andros::trainer {

double r3(double v) { return std::round(v * 1000.0) / 1000.0; }

namespace {

using nlohmann::json;

json point(vehicle::Point p) { return {r3(p.x), r3(p.y)}; }

json area(const vehicle::Area& a) {
  return {{"at", point(a.centre)}, {"size", {r3(a.length), r3(a.width)}}, {"heading", r3(a.heading)}};
}

}  // namespace

json course_map_json(const vehicle::Course& c) {
  json blocks = json::array();
  for (const auto& b : c.blocks) blocks.push_back({{"area", area(b.area)}, {"height", r3(b.height)}});
  json slopes = json::array();
  for (const auto& s : c.slopes) {
    slopes.push_back({{"area", area(s.area)}, {"angle", r3(s.angle)}, {"kind", s.stairs ? "stairs" : "ramp"}});
  }
  json landings = json::array();
  for (const auto& l : c.landings) landings.push_back({{"area", area(l.area)}, {"height", r3(l.height)}});
  json gates = json::array();
  for (const auto& g : c.gates)
    gates.push_back({{"at", point(g.at)}, {"heading", r3(g.heading)}, {"width", r3(g.width)}});
  json out = {{"name", c.name},
              {"ground", {{"x", {r3(c.min_x), r3(c.max_x)}}, {"y", {r3(c.min_y), r3(c.max_y)}}}},
              {"blocks", blocks},
              {"slopes", slopes},
              {"landings", landings},
              {"gates", gates},
              {"time_limit", r3(c.time_limit_s)}};
  if (c.door) {
    out["door"] = {
        {"hinge", point(c.door->hinge)}, {"width", r3(c.door->width)}, {"closed", r3(c.door->closed_heading)}};
  }
  if (c.package) {
    out["package"] = {{"size", r3(c.package->size)}};
    if (c.package->drop) out["package"]["drop"] = area(*c.package->drop);
  }
  if (c.finish) out["finish"] = area(c.finish->area);
  if (c.target) out["target"] = {{"at", point(c.target->at)}, {"z", r3(c.target->z)}, {"radius", r3(c.target->radius)}};
  return out;
}

json course_state_json(const vehicle::VehicleModel& model) {
  if (!model.course()) return nullptr;
  const auto& c = *model.course();
  const auto& s = model.state().course;
  json out = {{"elevation", r3(s.elevation)},
              {"pitch", r3(s.pitch)},
              {"contacts", s.contacts},
              {"touching", s.body_touching || s.arm_touching},
              {"climb_blocked", s.climb_blocked},
              {"gates", s.gates},
              {"tip_margin", r3(s.tip_margin)},
              {"tip_warning", s.tip_warning},
              {"tipped", s.tipped},
              {"laser_on_target", s.laser_on_target},
              {"in_finish", s.in_finish},
              {"done", model.course_done()}};
  if (c.door) out["door_angle"] = r3(s.door_angle);
  if (c.package) {
    out["package"] = {{"at", point(s.package)},
                      {"z", r3(s.package_z)},
                      {"held", s.package_held},
                      {"lifted", s.package_lifted},
                      {"delivered", s.package_delivered}};
  }
  return out;
}

}  // namespace andros::trainer
