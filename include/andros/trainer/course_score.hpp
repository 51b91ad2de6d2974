#pragma once
/// A training run's score on a course (docs/trainer.md, "The score"): what
/// the loop decided at each tick (its report: the frame sent, the state, the
/// stops) and what those frames did to the vehicle on the course. Fed the
/// same ticks, it gives the same score: the live trainer feeds it the loop's
/// reports, a recorded session's replay feeds it the same reports again.

#include <cstdint>
#include <string>
#include <vector>

#include "andros/run/bridge.hpp"
#include "andros/vehicle/vehicle_model.hpp"

namespace andros::trainer {

/// A stop during the run: when, whose, and why.
struct ScoredStop {
  std::int64_t t_ms = 0;
  std::string by;   ///< "operator", "supervisor", "gate"
  std::string why;  ///< "stop button", "stop button again", or the frame gate's fault
};

struct Score {
  std::string course;
  bool completed = false;  ///< done within the time limit, not tipped over
  /// "completed", or why not ("tipped over", "over the time limit", "not finished: gates 2/3, ...").
  std::string result;
  double time_s = 0;  ///< to the tick the course was done, or to the last tick
  double time_limit_s = 0;
  std::size_t gates = 0;
  std::size_t gates_total = 0;
  std::uint32_t contacts = 0;
  std::uint32_t climbs_refused = 0;
  std::uint32_t tip_warnings = 0;
  bool tipped = false;
  std::vector<ScoredStop> stops;
  /// Times it was enabled with an input not at rest (the engine held it back until released).
  std::uint32_t not_at_rest = 0;
  std::uint32_t fired = 0;
  std::uint32_t fired_off_target = 0;  ///< fired without the laser on the target
  std::uint32_t hits = 0;              ///< fired with the laser on the target
  /// Fire pressed, armed, without the supervisor's consent: refused by the engine.
  std::uint32_t fire_refused = 0;
  bool package_delivered = false;
};

/// One line of JSON (the session's `score` record, the page's `score`).
std::string score_json(const Score& score);
/// The score for the terminal: a few lines, each `  what: value` (the course's name escaped: printable_text).
std::string score_text(const Score& score);

class CourseScorer {
 public:
  CourseScorer(const vehicle::RobotFigures& figures, vehicle::Course course);

  /// A tick's report: its frame (when the link took it) into the vehicle, its state and stops noted.
  void on_tick(const run::TickReport& report);
  [[nodiscard]] Score score() const;
  [[nodiscard]] const vehicle::VehicleModel& model() const { return model_; }

 private:
  vehicle::VehicleModel model_;
  std::int64_t last_ms_ = 0;
  std::int64_t done_ms_ = -1;  ///< the tick the course was first done (-1: not yet)
  run::OpState last_state_ = run::OpState::kNoLink;
  std::uint32_t fire_refused_ = 0;
  bool fire_refusing_ = false;
  std::uint32_t not_at_rest_ = 0;
  std::vector<ScoredStop> stops_;
};

}  // namespace andros::trainer
