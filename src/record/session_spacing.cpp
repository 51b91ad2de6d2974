// check_record_spacing (andros/record/session.hpp): the ticks a session's
// frame records stand for, within kFrameRecordPeriodMs of each, in the
// formats whose writer keeps them so.
#include <optional>
#include <string>

#include "andros/base/error.hpp"
#include "andros/record/session.hpp"
#include "andros/timing/rate.hpp"

namespace andros::record {

std::optional<InputError> spacing_error(const Session& s, const FrameRecord& from, std::int64_t through, int line) {
  const timing::FrameClock clock(s.settings.rate_millihertz);
  const std::int64_t after = clock.time_of(through) - from.t_ms;
  if (after < kFrameRecordPeriodMs) return std::nullopt;
  return InputError(SourcePos{s.path, line}, "tick " + std::to_string(through) + " is " + std::to_string(after) +
                                                 " ms after the frame record it repeats (line " +
                                                 std::to_string(from.line) + "): format " +
                                                 std::to_string(kSpacedFormat) + " writes one every " +
                                                 std::to_string(kFrameRecordPeriodMs / kMsPerSecond) + " s at least");
}

void check_record_spacing(const Session& s, bool any_format, bool frames_checked) {
  // Records dropped leave ticks no record stands for: such a session keeps
  // the older formats' bound (24 h), and replay refuses it.
  if ((s.format < kSpacedFormat && !any_format) || s.dropped != 0) return;
  // The ticks from record i - 1 through those before record i repeat its frame.
  for (std::size_t i = 1; !frames_checked && i < s.frames.size(); ++i) {
    if (auto e = spacing_error(s, s.frames[i - 1], s.frames[i].tick - s.frames[i].gap - 1, s.frames[i].line)) throw *e;
  }
  if (!s.end || s.end->last_tick < 0) return;
  if (s.frames.empty()) {
    throw InputError(SourcePos{s.path, s.end->line},
                     "an end at tick " + std::to_string(s.end->last_tick) + " without a frame record before it");
  }
  if (auto e = spacing_error(s, s.frames.back(), s.end->last_tick, s.end->line)) throw *e;
}

}  // namespace andros::record
