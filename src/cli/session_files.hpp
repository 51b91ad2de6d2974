#pragma once
// Where the flight recorder's sessions live, their names, and their rotation
// (docs/recording.md).

#include <cstdint>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

namespace andros::cli {

/// configured (--record-dir, record_dir=) when given; else $STATE_DIRECTORY
/// (what systemd's StateDirectory= gives the service: /var/lib/andros-bridge),
/// else $XDG_STATE_HOME/andros-bridge, else ~/.local/state/andros-bridge.
std::filesystem::path session_dir(const std::string& configured);

/// A session named on the command line: as given when it is there (or names
/// a folder: has a '/'); else a bare name, as `sessions` prints it, from the
/// folder where `run` keeps them (session_dir(record_dir)), when it is there.
std::string find_session(const std::string& given, const std::string& record_dir = "");

/// A new session's path in dir: YYYYMMDD-HHMMSS-PID.andros-session, local time.
std::filesystem::path new_session_path(const std::filesystem::path& dir, std::time_t now, long pid);

/// The sessions in dir, oldest first (by name: the start time). None when dir does not exist.
std::vector<std::filesystem::path> list_sessions(const std::filesystem::path& dir);

struct RotationLimits {
  std::uint64_t max_bytes = 0;
  std::int64_t max_age_s = 0;  ///< by the time a session was last written
};

/// Removes whole sessions, oldest first, until the others take at most
/// max_bytes, and every one last written more than max_age ago; never keep
/// (the running session). Returns the ones removed.
std::vector<std::filesystem::path> rotate_sessions(const std::filesystem::path& dir, const RotationLimits& limits,
                                                   const std::filesystem::path& keep, std::time_t now);

}  // namespace andros::cli
