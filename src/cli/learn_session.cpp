#include "andros/cli/learn_session.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>

#include "andros/base/error.hpp"
#include "andros/base/output_file.hpp"
#include "andros/base/text.hpp"
#include "andros/mapping/loader.hpp"

namespace andros::cli {

namespace fs = std::filesystem;
using Key = Keyboard::Key;

Keyboard::Keyboard(int fd) : fd_(fd) {
  terminal_ = isatty(fd) == 1 && tcgetattr(fd, &saved_) == 0;
  if (!terminal_) return;
  termios raw = saved_;
  raw.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO | ISIG | IEXTEN);
  raw.c_iflag &= ~static_cast<tcflag_t>(IXON | ICRNL);
  raw.c_cc[VMIN] = 1;
  raw.c_cc[VTIME] = 0;
  if (tcsetattr(fd, TCSAFLUSH, &raw) != 0) terminal_ = false;
}

Keyboard::~Keyboard() {
  if (terminal_) tcsetattr(fd_, TCSAFLUSH, &saved_);
}

Key Keyboard::decode(char c) {
  switch (c) {
    case '\r':
    case '\n': return Key::kKeep;
    case 's': return Key::kSkipLayer;
    case 'b': return Key::kBack;
    case 'w': return Key::kWrite;
    case 'q':
    case 0x03:  // Ctrl-C
    case 0x04:  // Ctrl-D
      return Key::kQuit;
    default: return Key::kOther;
  }
}

Key Keyboard::read(int wait_ms) {
  const auto take = [&]() -> Key {
    if (terminal_) {
      if (pending_.empty()) return Key::kNone;
      const char c = pending_.front();
      pending_.erase(0, 1);
      return decode(c);
    }
    auto eol = pending_.find('\n');
    if (eol == std::string::npos && !(ended_ && !pending_.empty())) return Key::kNone;
    if (eol == std::string::npos) eol = pending_.size();
    std::string line = pending_.substr(0, eol);
    pending_.erase(0, eol + 1);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    return line.empty() ? Key::kKeep : line.size() == 1 ? decode(line[0]) : Key::kOther;
  };
  if (const Key k = take(); k != Key::kNone) return k;
  if (ended_) return Key::kQuit;
  pollfd p{fd_, POLLIN, 0};
  if (poll(&p, 1, wait_ms) <= 0) return Key::kNone;
  char buf[64];
  const ssize_t n = ::read(fd_, buf, sizeof buf);
  if (n < 0 && (errno == EINTR || errno == EAGAIN)) return Key::kNone;
  if (n <= 0) ended_ = true;
  else pending_.append(buf, static_cast<std::size_t>(n));
  const Key k = take();
  return k == Key::kNone && ended_ ? Key::kQuit : k;
}

LearnSession::LearnSession(mapping::LearnPlan& plan, input::LiveGestures& pad, Keyboard& keys, std::FILE* out)
    : plan_(plan), pad_(pad), keys_(keys), out_(out) {
  if (plan_.steps().empty()) end_ = End::kWrite;
}

void LearnSession::say(const std::string& line) {
  std::fprintf(out_, "%s\n", line.c_str());
  std::fflush(out_);
}

void LearnSession::go_to(std::size_t index) {
  index_ = index;
  prompted_ = false;
  if (index_ >= plan_.steps().size()) end_ = End::kWrite;
}

void LearnSession::report_controller() {
  if (pad_.connected() && pad_.connection() != connection_) {
    connection_ = pad_.connection();
    say("  controller: " + printable_text(pad_.name()));
  } else if (!pad_.connected() && (told_connected_ || connection_ == 0)) {
    if (told_connected_ || !told_waiting_) say("  no controller: waiting for " + pad_.selection());
    told_waiting_ = true;
  }
  told_connected_ = pad_.connected();
}

bool LearnSession::step(int wait_ms) {
  if (end_ != End::kRunning) return false;
  if (!prompted_) {
    say(plan_.prompt(index_));
    pad_.reset();
    prompted_ = true;
  }
  const auto gesture = pad_.poll();
  report_controller();
  if (gesture) return answer(*gesture);
  switch (keys_.read(wait_ms)) {
    case Key::kNone: break;
    case Key::kKeep:
      say("  kept " + plan_.current(index_));
      go_to(index_ + 1);
      return end_ == End::kRunning;
    case Key::kSkipLayer:
      say("  kept the rest of this layer");
      go_to(plan_.next_layer(index_));
      return end_ == End::kRunning;
    case Key::kBack: go_to(index_ == 0 ? 0 : index_ - 1); return true;
    case Key::kWrite: end_ = End::kWrite; return false;
    case Key::kQuit: end_ = End::kQuit; return false;
    case Key::kOther:
      say("  keys: Enter keeps, s skips the rest of this layer, b goes back, w writes now, q quits");
      break;
  }
  return true;
}

bool LearnSession::answer(const input::Gesture& gesture) {
  const auto result = plan_.assign(index_, gesture);
  if (result.kind == mapping::LearnResult::Kind::kRefused) {
    say("  refused: " + result.message + "; try another");
    pad_.reset();
    return true;
  }
  say("  " + result.message);
  go_to(index_ + 1);
  return end_ == End::kRunning;
}

namespace {

fs::path canonical_of(const fs::path& path) {
  std::error_code ec;
  return fs::weakly_canonical(fs::absolute(path), ec);
}

/// The robot's mapping as `extends: ROBOT` finds it from output: the first
/// on the search path other than output itself; empty when none is.
fs::path robot_mapping_past(const std::string& robot, const fs::path& output) {
  const auto file = to_lower(robot) + ".yaml";
  for (const auto& dir : mapping::mapping_search_path()) {
    std::error_code ec;
    if (!fs::is_regular_file(dir / file, ec)) continue;
    auto found = canonical_of(dir / file);
    if (found != output) return found;
  }
  return {};
}

}  // namespace

std::string extends_name(const fs::path& file, const std::optional<std::string>& robot, const fs::path& output) {
  const auto canonical = canonical_of(file);
  if (robot && robot_mapping_past(*robot, canonical_of(output)) == canonical) return to_lower(*robot);
  return canonical.string();
}

LearnTarget learn_target(const mapping::Mapping& base, const fs::path& output, bool force) {
  const SourcePos at{"--output"};
  std::error_code ec;
  if (fs::is_directory(output, ec)) throw InputError(at, quote_name(output.string()) + " is a folder");
  auto folder = fs::absolute(output).parent_path();
  while (!fs::exists(folder, ec) && folder.has_relative_path()) folder = folder.parent_path();
  if (!fs::is_directory(folder, ec)) throw InputError(at, quote_name(folder.string()) + " is not a folder");
  const bool exists = fs::exists(fs::symlink_status(output, ec));
  if (exists && !force) {
    throw InputError(
        at, quote_name(output.string()) +
                " exists: give --force to replace it (it is replaced only once the new file is written whole)");
  }
  const auto canonical = canonical_of(output);
  const auto& chain = base.chain;
  for (std::size_t i = 1; i < chain.size(); ++i) {
    if (fs::path(chain[i]) == canonical) {
      throw InputError(
          at, quote_name(output.string()) +
                  " is a file the mapping learned from extends: it would extend itself; write to another file");
    }
  }
  fs::path over = chain.empty() ? fs::path(base.file) : fs::path(chain.front());
  if (over == canonical) {
    // Learning again from one's own output: the new file extends what it extended.
    over = chain.size() > 1 ? fs::path(chain[1]) : robot_mapping_past(base.robot.value_or(""), canonical);
    if (over.empty()) {
      throw InputError(at, quote_name(output.string()) +
                               " is the mapping learned from and extends nothing: no robot mapping " +
                               "for it to extend on the search path; write to another file");
    }
    return LearnTarget{*mapping::load_mapping(over), extends_name(over, base.robot, output)};
  }
  return LearnTarget{base, extends_name(over, base.robot, output)};
}

void write_learned(const mapping::LearnPlan& plan, const std::string& text, const fs::path& output) {
  // Read as output itself: its errors name output, and `extends: ROBOT` passes over output as it will.
  if (!plan.matches(*mapping::load_mapping_text(text, output))) {
    throw RuntimeError("cannot write " + quote_name(output.string()) +
                       ": the file made does not read back as learned (a bug): nothing written");
  }
  const auto folder = fs::absolute(output).parent_path();
  std::error_code ec;
  if (!fs::is_directory(folder, ec) && !fs::create_directories(folder, ec) && ec) {
    throw RuntimeError("cannot make the folder " + quote_name(folder.string()) + ": " + ec.message());
  }
  write_output_file(output.string(), text);
}

void write_learned_or_show(const mapping::LearnPlan& plan, const std::string& text, const fs::path& output,
                           std::FILE* out) {
  try {
    write_learned(plan, text, output);
  } catch (const std::exception&) {
    std::fprintf(out, "%s not written; the learned mapping, to keep:\n%s", printable_text(output.string()).c_str(),
                 text.c_str());
    std::fflush(out);
    throw;
  }
}

}  // namespace andros::cli
