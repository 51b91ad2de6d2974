#include "andros/trainer/course_score.hpp"

#include <nlohmann/json.hpp>

#include "andros/base/text.hpp"
#include "andros/record/session.hpp"
#include "andros/trainer/course_view.hpp"
#include "andros/view/session_motion.hpp"

namespace andros::trainer {
namespace {

using nlohmann::json;

/// Why a run that is not completed is not.
std::string not_done(const Score& s, const vehicle::Course& c, const vehicle::CourseState& v) {
  if (s.tipped) return "tipped over";
  std::string out;
  const auto add = [&](const std::string& part) { out += (out.empty() ? "" : ", ") + part; };
  if (s.gates < s.gates_total) add("gates " + std::to_string(s.gates) + "/" + std::to_string(s.gates_total));
  if (c.package && c.package->drop && !v.package_delivered) add("the package not set down in its area");
  if (c.finish && !v.in_finish) add("not in the finish");
  if (c.target && v.hits == 0) add("the target not hit");
  return "not finished: " + out;
}

}  // namespace

CourseScorer::CourseScorer(const vehicle::RobotFigures& figures, vehicle::Course course)
    : model_(figures, std::move(course)) {}

void CourseScorer::on_tick(const run::TickReport& r) {
  last_ms_ = r.t_ms;
  // As the trainer's model and a session's replay take a tick (view::feed_tick).
  view::feed_tick(model_, r.t_ms, r.data, r.delivered());
  if (done_ms_ < 0 && model_.course_done()) done_ms_ = r.t_ms;
  // Every stop press (the machine's published steps: both pads' in one tick too).
  for (const auto& [t, pad] : r.transitions) {
    const auto by = run::stop_by(t.event);
    if (!by) continue;
    std::string why = t.again ? "stop button again" : "stop button";
    if (*by == run::StopBy::kGate) why = "frame gate: " + r.gate_fault;
    stops_.push_back({r.t_ms, std::string(record::stopper_word(*by)), why});
  }
  if (r.state == run::OpState::kEnabled && last_state_ != run::OpState::kEnabled && !r.engine.held_back.empty()) {
    ++not_at_rest_;
  }
  last_state_ = r.state;
  // A refusal counted once per press: held on, it is the same refusal.
  if (r.engine.fire_refused && !fire_refusing_) ++fire_refused_;
  fire_refusing_ = r.engine.fire_refused;
}

Score CourseScorer::score() const {
  const auto& c = *model_.course();
  const auto& v = model_.state().course;
  Score s;
  s.course = c.name;
  s.time_limit_s = c.time_limit_s;
  s.time_s = static_cast<double>(done_ms_ >= 0 ? done_ms_ : last_ms_) / 1000.0;
  s.gates = v.gates;
  s.gates_total = c.gates.size();
  s.contacts = v.contacts;
  s.climbs_refused = v.climbs_refused;
  s.tip_warnings = v.tip_warnings;
  s.tipped = v.tipped;
  s.stops = stops_;
  s.not_at_rest = not_at_rest_;
  for (const auto n : model_.state().fired) s.fired += n;
  s.fired_off_target = v.fired_off_target;
  s.hits = v.hits;
  s.fire_refused = fire_refused_;
  s.package_delivered = v.package_delivered;
  const bool late = c.time_limit_s > 0 && s.time_s > c.time_limit_s;
  s.completed = done_ms_ >= 0 && !late && !v.tipped;
  s.result = s.completed ? "completed" : late ? "over the time limit" : not_done(s, c, v);
  return s;
}

std::string score_json(const Score& s) {
  json stops = json::array();
  for (const auto& st : s.stops) stops.push_back({{"t_ms", st.t_ms}, {"by", st.by}, {"why", st.why}});
  // The course's name as printable text, as every text from outside is in a session.
  const json j = {{"course", printable_text(s.course)},
                  {"completed", s.completed},
                  {"result", s.result},
                  {"time_s", r3(s.time_s)},
                  {"time_limit_s", s.time_limit_s},
                  {"gates", s.gates},
                  {"gates_total", s.gates_total},
                  {"contacts", s.contacts},
                  {"climbs_refused", s.climbs_refused},
                  {"tip_warnings", s.tip_warnings},
                  {"tipped", s.tipped},
                  {"stops", stops},
                  {"not_at_rest", s.not_at_rest},
                  {"fired", s.fired},
                  {"fired_off_target", s.fired_off_target},
                  {"hits", s.hits},
                  {"fire_refused", s.fire_refused},
                  {"package_delivered", s.package_delivered}};
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string score_text(const Score& s) {
  char time[64];
  std::snprintf(time, sizeof time, "%.1f s", s.time_s);
  // The course's name is its file's text: escaped, as any text from outside is on the terminal.
  std::string out = "course " + printable_text(s.course) + ": " + s.result + "\n";
  out += std::string("  time: ") + time +
         (s.time_limit_s > 0 ? " (limit " + std::to_string(static_cast<long>(s.time_limit_s)) + " s)" : "") + "\n";
  out += "  gates: " + std::to_string(s.gates) + "/" + std::to_string(s.gates_total) + "\n";
  out += "  contacts: " + std::to_string(s.contacts) + "\n";
  out += "  stops: " + std::to_string(s.stops.size());
  for (const auto& st : s.stops) {
    out += "; " + std::to_string(st.t_ms / 1000) + "." + std::to_string(st.t_ms % 1000 / 100) + " s " + st.by + " (" +
           st.why + ")";
  }
  out += "\n  enabled with inputs not at rest: " + std::to_string(s.not_at_rest) + "\n";
  out += "  weapons: fired " + std::to_string(s.fired) + ", on the target " + std::to_string(s.hits) +
         ", without the laser on the target " + std::to_string(s.fired_off_target) + ", refused without consent " +
         std::to_string(s.fire_refused) + "\n";
  out += "  climbs refused: " + std::to_string(s.climbs_refused) +
         ", tipping warnings: " + std::to_string(s.tip_warnings) + ", tipped over: " + (s.tipped ? "yes" : "no") + "\n";
  return out;
}

}  // namespace andros::trainer
