// libFuzzer target: a session file (docs/recording.md) as verify, sessions,
// plot, export and replay read it (read_checked_session, the one reading).
// Any bytes either read or are refused with an InputError at the file (and a
// line in it); a last line cut short is never a record; what reads keeps a session's
// bounds (frame ticks in order at their times, within 24 h, the end at or
// after the last frame), the plot's samples and lanes are as many as its
// records, not its ticks, and a short session replays without a crash.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>

#include "andros/base/error.hpp"
#include "andros/record/session.hpp"
#include "andros/record/session_replay.hpp"
#include "andros/view/plot.hpp"
#include "andros/view/session_export.hpp"
#include "fuzz_check.hpp"
#include "scratch_dir.hpp"

using andros::fuzz::check;

namespace {

/// The fuzzer's bytes as a file: the readers take a path.
const std::string& input_path() {
  static const andros::fuzz::ScratchDir dir("session");
  static const std::string path = (dir.path() / "input.andros-session").string();
  return path;
}

/// The most ticks a seed's replay and export run: a fuzzer's minute, not a day's.
constexpr std::int64_t kTicksTried = 20'000;

void check_session(const andros::record::Session& s) {
  std::int64_t previous = -1;
  for (const auto& f : s.frames) {
    check(f.tick > previous && f.tick - f.gap > previous);
    check(f.t_ms >= 0 && f.t_ms <= andros::record::kMaxSessionMs);
    previous = f.tick;
  }
  if (s.end && !s.frames.empty()) check(s.end->last_tick >= s.frames.back().tick);
  const auto samples = andros::view::plot_samples(s);
  check(samples.size() <= 2 * (s.frames.size() + s.states.size() + s.layers.size()) + 2);
  // The plot's lanes: the events' work, a span at most per event, link record and reload.
  andros::view::PlotInput lanes;
  andros::view::add_lanes(lanes, s);
  for (const auto& lane : lanes.lanes) {
    check(lane.spans.size() <= s.events.size() + s.links.size() + s.reloads.size() + 1);
  }
  const std::int64_t last = s.end ? s.end->last_tick : (s.frames.empty() ? 0 : s.frames.back().tick);
  if (last > kTicksTried) return;
  std::ostringstream table;
  andros::view::export_session(s, andros::view::ExportFormat::kCsv, table);
  try {
    (void)andros::record::replay_session(s);
  } catch (const andros::InputError&) {
    // A mapping the session names that does not load, records dropped: refused, said.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& path = input_path();
  if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
    check(std::fwrite(data, 1, size, f) == size);
    std::fclose(f);
  }
  try {
    const auto checked = andros::record::read_checked_session(path);
    const auto& result = checked.verdict;
    check(result.intact || !result.problem.empty());
    if (result.intact) check(result.records > 0 && result.last_hash.size() == 64);
    // A line cut short, or a NUL tail, ends the reading: nothing after it closes the session.
    if (result.cut_short_line != 0) check(!result.closed && result.nul_tail == 0);
    check(checked.session.has_value() != checked.unreadable.has_value());
    if (checked.unreadable) check(checked.unreadable->pos().file == path);
    if (checked.session) check_session(*checked.session);
  } catch (const andros::InputError& e) {
    check(e.pos().file == path);
  }
  return 0;
}
