#pragma once
// The dialogue of `andros-bridge learn`: the operator's keys, the walk
// through the plan's steps, and the atomic write of the result. Apart from
// cmd_learn.cpp so that a test drives it with a pty and a virtual pad.

#include <termios.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
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

/// The path the written file names in `extends:`: relative to the output's
/// folder when the two share a folder other than the root, else absolute.
std::string extends_path(const std::filesystem::path& base, const std::filesystem::path& output);

/// Writes the plan's extending file to output atomically (a temporary file
/// in the same folder, renamed), after loading it with the real loader and
/// checking that it reads back as learned; on any failure nothing is written.
void write_learned(const mapping::LearnPlan& plan, const std::filesystem::path& base, const std::filesystem::path& output);

}  // namespace andros::cli
