#pragma once
// How validate()'s checks word an error: a signal's name, the line of the
// other place in a clash, and which of the two places is blamed.

#include <string>

#include "andros/base/error.hpp"
#include "andros/protocol/signals.hpp"

namespace andros::mapping {

inline std::string quoted_signal(protocol::SignalId id) { return "'" + std::string(protocol::info(id).name) + "'"; }

/// "line 12", or "line 12 of base.yaml" when other is in another file than here.
inline std::string line_of(const SourcePos& other, const SourcePos& here) {
  return "line " + std::to_string(other.line) + (other.file == here.file ? "" : " of " + other.file);
}

/// Of two places that clash, the one in the file being checked (the other
/// one is named in the message): an extending file's mistake is reported in
/// that file, at its line, not at the line of the base it runs into.
inline const SourcePos& blame(const std::string& file, const SourcePos& first, const SourcePos& second) {
  return first.file != file && second.file == file ? second : first;
}

inline void check_range(bool ok, const SourcePos& at, const std::string& what) {
  if (!ok) throw InputError(at, what + " is out of range");
}

}  // namespace andros::mapping
