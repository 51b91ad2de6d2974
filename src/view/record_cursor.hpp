#pragma once
// What a session's records say at a time, for the readers that walk a
// session tick by tick (the plot's samples, the export's rows): the
// operating state, the layer, the stop latched and the last stop's reset,
// each record taken in the order it was written (an enable ends who reset;
// a stop pressed again while stopped changes neither).

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>

#include "andros/record/session.hpp"

namespace andros::view {

class RecordCursor {
 public:
  explicit RecordCursor(const record::Session& s) : s_(s) {}

  /// Reads every state, stop and layer record at or before t.
  void at(std::int64_t t) {
    for (;;) {
      const bool state_due = state_at_ < s_.states.size() && s_.states[state_at_].t_ms <= t;
      const bool stop_due = stop_at_ < s_.stops.size() && s_.stops[stop_at_].t_ms <= t;
      if (state_due && (!stop_due || s_.states[state_at_].t_ms <= s_.stops[stop_at_].t_ms)) {
        state = s_.states[state_at_++].state;
        if (state == run::OpState::kEnabled) reset = nullptr;
      } else if (stop_due) {
        const auto& r = s_.stops[stop_at_++];
        if (r.again) continue;  // pressed again while stopped: whose the stop is did not change
        stop = r.reset ? nullptr : &r;
        reset = r.reset ? &r : nullptr;
      } else {
        break;
      }
    }
    while (layer_at_ < s_.layers.size() && s_.layers[layer_at_].t_ms <= t) layer = s_.layers[layer_at_++].text;
  }

  /// The time of the first state, stop or layer record not read yet; the largest time when none is left.
  [[nodiscard]] std::int64_t next_change() const {
    std::int64_t next = std::numeric_limits<std::int64_t>::max();
    if (state_at_ < s_.states.size()) next = std::min(next, s_.states[state_at_].t_ms);
    if (stop_at_ < s_.stops.size()) next = std::min(next, s_.stops[stop_at_].t_ms);
    if (layer_at_ < s_.layers.size()) next = std::min(next, s_.layers[layer_at_].t_ms);
    return next;
  }

  run::OpState state = run::OpState::kNoLink;
  std::string layer;
  const record::StopRecord* stop = nullptr;   ///< the stop latched: until its reset
  const record::StopRecord* reset = nullptr;  ///< the last stop's reset: until the next stop or an enable

 private:
  const record::Session& s_;
  std::size_t state_at_ = 0;
  std::size_t stop_at_ = 0;
  std::size_t layer_at_ = 0;
};

}  // namespace andros::view
