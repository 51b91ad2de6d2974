#include "andros/trainer/trainer_replay.hpp"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>

#include "andros/base/sha256.hpp"
#include "andros/base/text.hpp"
#include "andros/trainer/course_file.hpp"
#include "andros/trainer/course_view.hpp"
#include "andros/trainer/trainer_feed.hpp"
#include "andros/vehicle/robot_figures.hpp"

namespace andros::trainer {
namespace {

using nlohmann::json;

json figures_json(const vehicle::RobotFigures& f) {
  return {{"length", f.length_m.value},       {"width", f.width_m.value},     {"height", f.height_m.value},
          {"upper_arm", f.upper_arm_m.value}, {"forearm", f.forearm_m.value}, {"flipper", f.flipper_m.value}};
}

std::string upper(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::toupper(c); });
  return out;
}

std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

}  // namespace

std::optional<vehicle::Course> recorded_course(const record::Session& session) {
  if (!session.course) return std::nullopt;
  return parse_course(session.course->path.empty() ? session.course->name : session.course->path, session.course->text);
}

std::string trail_summary(const vehicle::VehicleModel& model) {
  // Hexadecimal floating point: every bit of every point, in the digest.
  std::string bits;
  for (const auto& p : model.trail()) bits += fmt::format("{:a} {:a}\n", p.x, p.y);
  const auto& e = model.state().pose;
  bits += fmt::format("end {:a} {:a} {:a}\n", e.x, e.y, e.heading);
  return fmt::format("ended at x {:.3f} m, y {:.3f} m, heading {:.3f} deg; trail {} points, SHA-256 {}", e.x, e.y,
                     e.heading, model.trail().size(), sha256_hex(bits));
}

SessionReplay::SessionReplay(record::Session session, std::string note)
    : session_(std::move(session)),
      note_(std::move(note)),
      motion_(session_, vehicle::figures_for(session_.settings.robot), recorded_course(session_)),
      samples_(view::plot_samples(session_, view::PlotAxis{0, -1})) {}

const view::PlotSample* SessionReplay::sample_at(std::int64_t t_ms) const {
  if (samples_.empty()) return nullptr;
  const auto after = std::upper_bound(samples_.begin(), samples_.end(), t_ms,
                                      [](std::int64_t t, const view::PlotSample& s) { return t < s.t_ms; });
  return after == samples_.begin() ? &samples_.front() : &*std::prev(after);
}

std::string SessionReplay::object(const vehicle::VehicleModel& model, std::int64_t tick, std::int64_t t_ms) const {
  LoopFacts facts{
      .tick = tick, .t_ms = t_ms, .state = "no tick yet", .state_name = "", .layer = "", .pad = {}, .score = {}};
  if (const auto* s = sample_at(t_ms)) {
    facts.state = upper(view::state_swatch(*s).name);
    facts.state_name = std::string(run::to_string(s->state));
    facts.layer = printable_text(s->layer);
  }
  return stream_object(model, facts);
}

std::string SessionReplay::state_at(std::int64_t t_ms) const {
  std::int64_t tick = -1;
  const auto model = motion_.at(t_ms, &tick);
  return object(model, tick, std::min(t_ms, motion_.length_ms()));
}

std::string SessionReplay::end_state() const {
  const auto& model = motion_.end();
  auto out = json::parse(object(model, session_.end ? session_.end->last_tick : -1, motion_.length_ms()));
  json trail = json::array();
  for (const auto& p : model.trail()) trail.push_back({r3(p.x), r3(p.y)});
  out["trail"] = std::move(trail);
  out["figures"] = figures_json(model.figures());
  if (model.course()) out["course_map"] = course_map_json(*model.course());
  return dump(out);
}

std::string SessionReplay::replay_json() const {
  json trail = json::array();
  for (const auto& p : motion_.trail()) trail.push_back({p.t_ms, r3(p.x), r3(p.y)});
  // The state lane: a run of samples in one colour is one span.
  json lane = json::array();
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    const auto swatch = view::state_swatch(samples_[i]);
    const std::string name(swatch.name);
    if (!lane.empty() && lane.back()["name"] == name) continue;
    lane.push_back({{"from", samples_[i].t_ms}, {"name", name}, {"colour", std::string(swatch.colour)}});
  }
  json out = {{"replay", true},
              {"session", printable_text(session_.path)},
              {"note", printable_text(note_)},
              {"robot", printable_text(session_.settings.robot)},
              {"length_ms", motion_.length_ms()},
              {"trail", std::move(trail)},
              {"lane", std::move(lane)},
              {"figures", figures_json(motion_.end().figures())}};
  // A trainer run's course, drawn as the live page draws it (from the recorded text).
  if (motion_.end().course()) out["course_map"] = course_map_json(*motion_.end().course());
  return dump(out);
}

}  // namespace andros::trainer
