#include "session_files.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <string_view>

#include "andros/base/unique_fd.hpp"

#include "andros/record/session.hpp"

namespace andros::cli {
namespace fs = std::filesystem;

namespace {

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v == nullptr ? std::string() : std::string(v);
}

/// The file at path opened for reading when it is a regular file (a link is
/// not followed) whose first line starts a session; else an empty descriptor.
UniqueFd open_session(const fs::path& path) {
  UniqueFd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY));
  struct stat st {};
  if (!fd || ::fstat(fd.get(), &st) != 0 || !S_ISREG(st.st_mode)) return {};
  char first[64];
  const auto n = ::pread(fd.get(), first, sizeof first, 0);
  if (n <= 0 || !record::is_session_start(std::string_view(first, static_cast<std::size_t>(n)))) return {};
  return fd;
}

}  // namespace

fs::path session_dir(const std::string& configured) {
  if (!configured.empty()) return configured;
  // systemd may give several (StateDirectory=a b): the first is ours.
  if (auto state = env("STATE_DIRECTORY"); !state.empty()) return state.substr(0, state.find(':'));
  if (auto xdg = env("XDG_STATE_HOME"); !xdg.empty() && fs::path(xdg).is_absolute())
    return fs::path(xdg) / "andros-bridge";
  return fs::path(env("HOME")) / ".local/state/andros-bridge";
}

std::string find_session(const std::string& given, const std::string& record_dir) {
  std::error_code ec;
  if (given.empty() || given == "-" || given.find('/') != std::string::npos ||
      fs::exists(fs::symlink_status(given, ec)))
    return given;
  const auto there = session_dir(record_dir) / given;
  return fs::exists(fs::symlink_status(there, ec)) ? there.string() : given;
}

fs::path new_session_path(const fs::path& dir, std::time_t now, long pid) {
  std::tm local{};
  localtime_r(&now, &local);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  return dir / (std::string(stamp) + "-" + std::to_string(pid) + std::string(record::kSessionExtension));
}

std::vector<fs::path> list_sessions(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.path().extension() == record::kSessionExtension && open_session(entry.path()))
      out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<fs::path> rotate_sessions(const fs::path& dir, const RotationLimits& limits, const fs::path& keep,
                                      std::time_t now) {
  struct Entry {
    fs::path path;
    std::uint64_t size;
    std::time_t written;
  };
  struct stat kept {};
  const bool keeping = !keep.empty() && ::stat(keep.c_str(), &kept) == 0;
  std::vector<Entry> sessions;
  std::uint64_t total = 0;
  for (const auto& path : list_sessions(dir)) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) continue;
    sessions.push_back({path, static_cast<std::uint64_t>(st.st_size), st.st_mtime});
    total += static_cast<std::uint64_t>(st.st_size);
  }
  std::vector<fs::path> removed;
  for (const auto& s : sessions) {  // oldest first
    if (s.path == keep) continue;
    const bool too_old = now - s.written > limits.max_age_s;
    if (!too_old && total <= limits.max_bytes) continue;
    // Only a closed session of its own: a session (its first line says so)
    // that no writer holds locked (a bridge running in this folder holds its
    // own), and never the running one, by whatever path it is named.
    const UniqueFd fd = open_session(s.path);
    struct stat st {};
    if (!fd || ::fstat(fd.get(), &st) != 0) continue;
    if (keeping && st.st_dev == kept.st_dev && st.st_ino == kept.st_ino) continue;
    if (::flock(fd.get(), LOCK_EX | LOCK_NB) != 0) continue;
    std::error_code ec;
    if (fs::remove(s.path, ec)) {
      removed.push_back(s.path);
      total -= s.size;
    }
  }
  return removed;
}

}  // namespace andros::cli
