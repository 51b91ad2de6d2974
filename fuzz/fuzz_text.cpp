// libFuzzer target: the bounded text reader every text input goes through.
// Arbitrary bytes under arbitrary limits, from memory or through a pipe,
// with a stop request at a random point (or whenever the pipe runs dry while
// its writer stays): the reader returns lines within the limits that are the
// input's own, an InputError inside the input, or ReadStopped, and never
// waits for input that cannot come.
//
// Input layout: flags (bit 0: through a pipe, bit 1: the writer stays open),
// the stop check that says stop (0: none), max_line, max_bytes (2 bytes),
// then the text.
#include <fcntl.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/base/text_file.hpp"
#include "fuzz_check.hpp"

using andros::fuzz::check;

namespace {

constexpr std::size_t kHeader = 5;
constexpr std::size_t kMaxText = 60'000;  // fits a pipe's buffer: no writer thread needed

struct Stopped {
  bool operator==(const Stopped&) const = default;
};
/// The lines read, or the line an InputError named, or a stop.
using Outcome = std::variant<std::vector<std::string>, int, Stopped>;

Outcome read_lines(andros::TextReader& text, const std::string& name) {
  std::vector<std::string> lines;
  try {
    while (const auto line = text.next_line()) lines.emplace_back(*line);
  } catch (const andros::InputError& e) {
    check(e.pos().file == name && e.pos().line >= 1);
    return e.pos().line;
  } catch (const andros::ReadStopped&) {
    return Stopped{};
  }
  return lines;
}

/// Lines that are the text's own, in order, within the limits.
void check_lines(const std::vector<std::string>& lines, const std::string& text, const andros::TextLimits& limits) {
  std::size_t at = 0;
  for (const auto& line : lines) {
    check(line.size() <= limits.max_line);
    check(text.compare(at, line.size(), line) == 0);
    at += line.size();
    check(at == text.size() || text[at] == '\n');
    if (at < text.size()) ++at;
    check(at <= limits.max_bytes);
  }
  check(at == text.size());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < kHeader) return 0;
  const bool through_pipe = (data[0] & 1) != 0;
  const bool writer_stays = (data[0] & 2) != 0;
  const int stop_at = data[1];
  const andros::TextLimits limits{"fuzz text", static_cast<std::size_t>(data[3] | data[4] << 8) + 1,
                                  static_cast<std::size_t>(data[2]) + 1};
  std::string text(reinterpret_cast<const char*>(data + kHeader), size - kHeader);
  if (text.size() > kMaxText) text.resize(kMaxText);

  andros::TextReader memory(text, "fuzz.txt", limits);
  const auto in_memory = read_lines(memory, "fuzz.txt");
  check(!std::holds_alternative<Stopped>(in_memory));
  if (const auto* lines = std::get_if<std::vector<std::string>>(&in_memory)) {
    check_lines(*lines, text, limits);
    memory.rewind();
    check(read_lines(memory, "fuzz.txt") == in_memory);
  }
  if (!through_pipe) return 0;

  int fds[2];
  check(::pipe2(fds, O_CLOEXEC) == 0);
  check(::write(fds[1], text.data(), text.size()) == static_cast<ssize_t>(text.size()));
  if (!writer_stays) ::close(fds[1]);
  int asked = 0;
  const auto stop = [&] {
    int unread = 0;
    ::ioctl(fds[0], FIONREAD, &unread);
    return ++asked == stop_at || (writer_stays && unread == 0);
  };
  const std::string name = "/dev/fd/" + std::to_string(fds[0]);
  Outcome piped;
  {
    auto reader = andros::TextReader::open(name, limits, stop);
    check(!reader.can_rewind());
    piped = read_lines(reader, name);
  }
  ::close(fds[0]);
  if (writer_stays) ::close(fds[1]);
  // Stopped, or the same outcome as from memory.
  check(std::holds_alternative<Stopped>(piped) || piped == in_memory);
  check(!std::holds_alternative<Stopped>(piped) || writer_stays || stop_at != 0);
  return 0;
}
