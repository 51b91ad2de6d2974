#include "andros/cli/learn_session.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "andros/base/error.hpp"
#include "andros/base/write_fully.hpp"
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
    say("  controller: " + pad_.name());
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
    case Key::kBack:
      go_to(index_ == 0 ? 0 : index_ - 1);
      return true;
    case Key::kWrite: end_ = End::kWrite; return false;
    case Key::kQuit: end_ = End::kQuit; return false;
    case Key::kOther: say("  keys: Enter keeps, s skips the rest of this layer, b goes back, w writes now, q quits"); break;
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

std::string extends_path(const fs::path& base, const fs::path& output) {
  const auto from = fs::weakly_canonical(fs::absolute(output)).parent_path();
  const auto to = fs::weakly_canonical(fs::absolute(base));
  const auto a = std::next(from.begin());
  const auto b = std::next(to.begin());
  const bool shared = a != from.end() && b != to.end() && *a == *b;
  return shared ? fs::relative(to, from).string() : to.string();
}

void write_learned(const mapping::LearnPlan& plan, const fs::path& base, const fs::path& output) {
  const auto text = plan.extending_yaml(extends_path(base, output));
  const auto folder = fs::absolute(output).parent_path();
  std::string tmp = (folder / ("." + output.filename().string() + ".XXXXXX")).string();
  const int fd = mkstemp(tmp.data());
  if (fd < 0) throw RuntimeError(output.string() + ": cannot create a temporary file: " + std::strerror(errno));
  bool open = true;
  try {
    const mode_t mask = umask(0);  // mkstemp makes 0600: give the file the mode a new file gets
    umask(mask);
    const int error = write_fully(fd, text);
    if (error != 0 || fchmod(fd, 0666 & ~mask) != 0 || fsync(fd) != 0) {
      throw RuntimeError(output.string() + ": write error: " + std::strerror(error != 0 ? error : errno));
    }
    open = false;
    if (close(fd) != 0) throw RuntimeError(output.string() + ": write error: " + std::strerror(errno));
    if (!plan.matches(*mapping::load_mapping(tmp))) {
      throw RuntimeError(output.string() + ": the file made does not read back as learned (a bug): nothing written");
    }
    if (std::rename(tmp.c_str(), output.c_str()) != 0) throw RuntimeError(output.string() + ": " + std::strerror(errno));
  } catch (...) {
    if (open) close(fd);
    unlink(tmp.c_str());
    throw;
  }
}

}  // namespace andros::cli
