#pragma once
// What an investigator looks for first in a session (`sessions`,
// docs/recording.md): whether weapons fired, the stops and by whom, the
// controllers and the link lost; each counted from the records exactly as
// docs/recording.md, "Sessions", defines it.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "andros/record/session.hpp"

namespace andros::cli {

struct SessionSummary {
  /// A weapon signal (kind weapon: weapon_1..., shotgun, laser, enable_key)
  /// set in a frame the link took (result `sent`) while the state was enabled.
  bool weapons_fired = false;
  std::vector<std::string> weapons;           ///< those that fired, in frame order
  std::optional<std::int64_t> first_fire_ms;  ///< when the first fired
  /// `stop` records by whose (StopBy: operator, supervisor, gate): a stop that
  /// latched, or an operator's stop the supervisor's stop button made its own.
  std::array<int, 3> stops{};
  std::array<int, 2> resets{};  ///< `reset` records: by the operator, by the supervisor
  /// A `disconnect` of a controller that was connected (a connect before it):
  /// the operator's, the supervisor's. Not one absent from the start.
  std::array<int, 2> controllers_lost{};
  /// A `link` record not up after one that was up, but for the bridge's own
  /// close (detail "closed": a suspend, the end): the link lost. The link
  /// before the first tick is none.
  int links_lost = 0;

  [[nodiscard]] int stop_count() const { return stops[0] + stops[1] + stops[2]; }
  [[nodiscard]] int controllers_lost_count() const { return controllers_lost[0] + controllers_lost[1]; }
};

SessionSummary summarize_session(const record::Session& session);

}  // namespace andros::cli
