#include "andros/link/port_holder.hpp"

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <vector>

namespace andros::link {
namespace {

std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

template <typename T>
std::optional<T> whole_number(std::string_view text, int base) {
  T value{};
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, base);
  if (text.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

/// /proc/PID/comm without its newline, printable ASCII only: a process names
/// itself (prctl), and the name goes into log lines and onto the screen.
std::string program_name(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/comm");
  std::string name;
  if (!std::getline(in, name)) return {};
  std::ranges::replace_if(
      name, [](char c) { return c < 0x20 || c > 0x7e; }, '?');
  return name;
}

}  // namespace

std::optional<int> lock_owner(std::string_view line, const LockedFile& file) {
  // "1: FLOCK  ADVISORY  WRITE 1234 00:1a:3 0 EOF": number, type, mode,
  // read/write, PID, MAJOR:MINOR:INODE (the device in hex), range. A process
  // waiting for the lock is listed under it with "->" and holds nothing.
  const auto words = words_of(line);
  if (words.size() < 6 || !words[0].ends_with(':')) return std::nullopt;
  if (std::ranges::find(words, "->") != words.end()) return std::nullopt;
  const auto pid = whole_number<int>(words[4], 10);
  if (!pid || *pid <= 0) return std::nullopt;  // -1: an OFD lock; 0: a PID not visible from here
  const std::string_view where = words[5];
  const auto first = where.find(':');
  const auto second = first == std::string_view::npos ? first : where.find(':', first + 1);
  if (second == std::string_view::npos) return std::nullopt;
  const auto dev_major = whole_number<unsigned>(where.substr(0, first), 16);
  const auto dev_minor = whole_number<unsigned>(where.substr(first + 1, second - first - 1), 16);
  const auto inode = whole_number<std::uint64_t>(where.substr(second + 1), 10);
  if (!dev_major || !dev_minor || !inode) return std::nullopt;
  if (*dev_major != file.dev_major || *dev_minor != file.dev_minor || *inode != file.inode) return std::nullopt;
  return pid;
}

PortHolder find_port_holder(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return {};
  const LockedFile file{major(st.st_dev), minor(st.st_dev), st.st_ino};
  std::ifstream locks("/proc/locks");
  for (std::string line; std::getline(locks, line);) {
    if (const auto pid = lock_owner(line, file)) return {*pid, program_name(*pid)};
  }
  return {};
}

std::string describe(const PortHolder& holder) {
  if (holder.pid <= 0) return "another program";
  const std::string pid = "(PID " + std::to_string(holder.pid) + ")";
  return (holder.program.empty() ? std::string("another program") : holder.program) + " " + pid;
}

}  // namespace andros::link
