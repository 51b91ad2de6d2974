#pragma once
// The dialogue of `andros-bridge learn`: the operator's keys, the walk
// through the plan's steps, and the atomic write of the result. Apart from
// cmd_learn.cpp so that a test drives it with a pty and a virtual pad.

#include <termios.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "andros/input/live_gestures.hpp"
#include "andros/mapping/learn.hpp"

namespace andros::cli {

/// The operator's keys. On a terminal: one key at a time, no echo, Ctrl-C a
/// key like any other (no signal), the terminal's settings restored when this
/// ends. Anything else: one command per line.
class Keyboard {
 public:
  enum class Key { kNone, kKeep, kSkipLayer, kBack, kWrite, kQuit, kOther };

  explicit Keyboard(int fd);
  ~Keyboard();
  Keyboard(const Keyboard&) = delete;
  Keyboard& operator=(const Keyboard&) = delete;

  /// The next key, waiting at most wait_ms; kNone when none came. The end of
  /// the input (Ctrl-D on a terminal) is kQuit.
  Key read(int wait_ms);
  [[nodiscard]] bool terminal() const { return terminal_; }

 private:
  Key decode(char c);

  int fd_;
  bool terminal_ = false;
  termios saved_{};
  std::string pending_;  ///< bytes read, not yet decoded
  bool ended_ = false;
};

/// Walks the plan: for each step a prompt, then a controller input (assigned,
/// or refused with the reason and asked again) or a key.
class LearnSession {
 public:
  enum class End { kRunning, kWrite, kQuit };

  LearnSession(mapping::LearnPlan& plan, input::LiveGestures& pad, Keyboard& keys, std::FILE* out);

  /// One turn: waits at most wait_ms for a key, reads the controller, acts.
  /// Returns false once the walk has ended (end() says how).
  bool step(int wait_ms);
  [[nodiscard]] End end() const { return end_; }

 private:
  void go_to(std::size_t index);
  void say(const std::string& line);
  void report_controller();
  bool answer(const input::Gesture& gesture);

  mapping::LearnPlan& plan_;
  input::LiveGestures& pad_;
  Keyboard& keys_;
  std::FILE* out_;
  std::size_t index_ = 0;
  bool prompted_ = false;
  End end_ = End::kRunning;
  std::uint32_t connection_ = 0;  ///< the pad's connection last reported
  bool told_connected_ = false;
  bool told_waiting_ = false;
};

/// What `learn --output FILE` writes over and extends.
struct LearnTarget {
  mapping::Mapping over;  ///< the mapping the written file extends: its bindings are what the file changes
  std::string extends;    ///< how `extends:` names it (extends_name)
};

/// Checks FILE and chooses what the written file extends, before the
/// session starts (an InputError at --output): FILE is not a folder, its
/// nearest existing folder is a folder; an existing FILE only with force.
/// Learning from FILE itself (the second run on one's own output) writes a
/// file that extends what FILE extended (or, for a file that extends
/// nothing, the robot's mapping the search path finds past FILE); a FILE
/// that the mapping learned from extends is refused (it would extend itself).
LearnTarget learn_target(const mapping::Mapping& base, const std::filesystem::path& output, bool force);

/// How the written file names the file it extends: the robot in lower case
/// (`extends: hd1`, docs/mapping.md) when the mapping search path, with
/// output itself passed over, finds that very file for the robot, so that
/// the file keeps working when copied elsewhere; else the file's absolute path.
std::string extends_name(const std::filesystem::path& file, const std::optional<std::string>& robot,
                         const std::filesystem::path& output);

/// Writes text, the plan's extending file, to output (base/output_file.hpp:
/// whole or not at all, a link followed, the mode kept), after loading it
/// under output's own name with the real loader and checking that it reads
/// back as learned; makes output's missing folders. On any failure nothing
/// is written and the error names output.
void write_learned(const mapping::LearnPlan& plan, const std::string& text, const std::filesystem::path& output);

/// write_learned(); when it fails, the session is not lost: text goes to out
/// ("FILE not written; the learned mapping, to keep:" and the YAML) before
/// the error is thrown on.
void write_learned_or_show(const mapping::LearnPlan& plan, const std::string& text, const std::filesystem::path& output,
                           std::FILE* out);

}  // namespace andros::cli
