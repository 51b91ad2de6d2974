#pragma once
/// A recorded session through the run loop again (docs/recording.md): the
/// same Bridge on a virtual clock that the session moves as the live clock
/// moved (a stall's skipped ticks, a Ctrl-Z's pause), the recorded input
/// events, requests, reload outcomes and link results played back at the
/// ticks they came, and the engine made from the recorded mapping text. Every
/// frame the live loop handed to the link is compared with the replay's, and
/// every record the loop writes (record_check.hpp) with the session's.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "andros/mapping/engine.hpp"
#include "andros/record/session.hpp"
#include "andros/run/bridge.hpp"

namespace andros::record {

struct SessionReplayResult {
  std::uint64_t compared = 0;  ///< frames sent live that the replay reproduced byte for byte
  std::uint64_t ticks = 0;     ///< ticks the replay ran (its work: at most the session's ticks and a stop's few)
  /// Every frame and every record the loop decides (request, gate, state,
  /// stop, reset, layer, frame) made again the same, in the file's order.
  bool identical = false;
  std::string difference;     ///< the first difference, when not identical: its line and both texts
  std::uint64_t records = 0;  ///< the session's records of those kinds made again the same
  /// Records of a session not closed after its last frame record: the replay
  /// does not run the ticks they came in (what the live loop sent then is not
  /// known), so they are neither proven nor different.
  std::uint64_t unproven = 0;
  int first_unproven_line = 0;
  /// Every record of the session proven by the replay.
  [[nodiscard]] bool proven() const { return identical && unproven == 0; }
};

/// The mapping a session's files make (the first file is the mapping).
/// Throws InputError.
using SourcesLoader = std::function<mapping::ValidMapping(const std::vector<MappingSource>& sources)>;

/// Loads recorded mapping files in memory (mapping::load_recorded_chain): a
/// recorded path is a label, `extends` takes the next recorded file; nothing
/// is written, and nothing of this machine's mappings is read.
mapping::ValidMapping load_recorded_mapping(const std::vector<MappingSource>& sources);

/// The mappings the session ran with, in order: the recorded one, then
/// each ok reload's (ReloadRecord::settings). Throws InputError.
std::vector<mapping::ValidMapping> recorded_mappings(const Session& session,
                                                     const SourcesLoader& load = load_recorded_mapping);

/// Replays session; observe sees every tick's report (the plot's source).
/// Throws InputError for a session that cannot be replayed exactly (records
/// dropped, an unknown mapping).
SessionReplayResult replay_session(const Session& session, const SourcesLoader& load = load_recorded_mapping,
                                   const run::Bridge::Observer& observe = {});

}  // namespace andros::record
