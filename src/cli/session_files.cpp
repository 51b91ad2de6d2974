#include "session_files.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>

#include "andros/run/session.hpp"

namespace andros::cli {
namespace fs = std::filesystem;

namespace {

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v == nullptr ? std::string() : std::string(v);
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

fs::path new_session_path(const fs::path& dir, std::time_t now, long pid) {
  std::tm local{};
  localtime_r(&now, &local);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  return dir / (std::string(stamp) + "-" + std::to_string(pid) + std::string(run::kSessionExtension));
}

std::vector<fs::path> list_sessions(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.path().extension() == run::kSessionExtension && entry.is_regular_file(ec)) out.push_back(entry.path());
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
  std::vector<Entry> sessions;
  std::uint64_t total = 0;
  for (const auto& path : list_sessions(dir)) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) continue;
    sessions.push_back({path, static_cast<std::uint64_t>(st.st_size), st.st_mtime});
    total += static_cast<std::uint64_t>(st.st_size);
  }
  std::vector<fs::path> removed;
  for (const auto& s : sessions) {  // oldest first
    if (s.path == keep) continue;
    const bool too_old = now - s.written > limits.max_age_s;
    if (!too_old && total <= limits.max_bytes) continue;
    std::error_code ec;
    if (fs::remove(s.path, ec)) {
      removed.push_back(s.path);
      total -= s.size;
    }
  }
  return removed;
}

}  // namespace andros::cli
