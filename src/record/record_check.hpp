#pragma once
// A replay's records against a session's (docs/recording.md, "Replay"): the
// replay's Recorder makes every record the loop writes, and each of the kinds
// the loop decides (request, gate, state, transition, stop, reset, layer, frame) is
// compared with the next the session holds of its kind, as text made by the
// same payload functions, and in the file's order. The inputs (event, pause,
// reload, settings, link, input-end) are what the replay was given.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "andros/record/session.hpp"

namespace andros::record {

class RecordCheck {
 public:
  explicit RecordCheck(const Session& session) : s_(session) {}

  /// One payload the replay's recorder made (any kind; the inputs are passed over).
  void made(std::string_view payload);
  /// After the replayed ticks: the records of the decided kinds left over.
  /// A session closed by its end record has none; one cut off may hold the
  /// records of its last ticks after its last frame record, which the replay
  /// did not run: those are counted as unproven, not called different.
  void finish();

  /// The first difference is kept: a tick's frame, or one of the records.
  void differ(std::string what);
  [[nodiscard]] const std::string& difference() const { return difference_; }
  /// The session's records matched so far.
  [[nodiscard]] std::uint64_t matched() const;
  /// Records of a session not closed after its last frame record: not replayed.
  [[nodiscard]] std::uint64_t unproven() const { return unproven_; }
  [[nodiscard]] int first_unproven_line() const { return first_unproven_line_; }

 private:
  /// The decided kinds, each a list of the session's in the order read.
  enum Kind : std::uint8_t { kRequest, kGate, kState, kTransition, kStop, kLayer, kFrame, kKinds };
  struct Recorded {
    std::string text;  ///< as the payload function writes it
    std::int64_t t_ms = 0;
    int line = 0;
  };
  [[nodiscard]] std::size_t count(Kind kind) const;
  [[nodiscard]] Recorded recorded(Kind kind, std::size_t i) const;
  /// A stop or reset of an earlier version (no PAD) against the replay's: the time, who and name.
  [[nodiscard]] static bool same_old_stop(const StopRecord& old, std::string_view made);

  const Session& s_;
  std::array<std::size_t, kKinds> next_{};
  int last_line_ = 0;  ///< the last record matched
  std::string difference_;
  std::uint64_t unproven_ = 0;
  int first_unproven_line_ = 0;
};

}  // namespace andros::record
