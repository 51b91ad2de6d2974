#pragma once
/// The live controller: SDL2's game-controller API for pads SDL knows, its
/// joystick API for the rest, turned into InputEvents for one chosen device.
/// Single-threaded: construct it (SDL_Init happens here) before any thread
/// starts, and call pump()/poll() from one thread only.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/base/text_file.hpp"
#include "andros/input/device_layout.hpp"
#include "andros/input/input_source.hpp"
#include "andros/input/input_state.hpp"

namespace andros::input {

/// Where SDL says a device is, and which unit it is: SDL 2.26 gives a device
/// node (/dev/input/eventN, /dev/hidrawN) for the pads it reads through
/// evdev or HIDAPI, and a serial for those whose driver reads one. Each
/// function returns "" where SDL gives none. Empty functions read SDL's
/// (SDL_JoystickPathForIndex, SDL_JoystickGetSerial); tests stand in for SDL
/// here, whose virtual pads have neither.
struct PadPlaces {
  std::function<std::string(int device_index)> path;
  std::function<std::string(int device_index)> serial;
};

/// How to choose the controller and which extra SDL mappings to load.
struct SdlInputOptions {
  /// INDEX (a position in `andros-bridge controllers`), GUID (32 hex digits),
  /// PATH (a device node, or a link to one such as /dev/input/by-path/...:
  /// the pad in that port) or NAME (case-insensitive, a part of the name is
  /// enough). Empty: the first controller found.
  std::string controller;
  /// A file of extra SDL controller mappings (gamecontrollerdb.txt format).
  /// Empty: none beyond SDL's own and SDL_GAMECONTROLLERCONFIG.
  std::string controller_db;
  /// The supervisor's controller, chosen as `controller` is (never the same
  /// device). Empty: none.
  std::string supervisor;
  SourcePos supervisor_pos{"--supervisor"};  ///< where it was set, for errors about it
  PadPlaces places;                          ///< SDL's device paths and serials
};

/// One attached device, as `andros-bridge controllers` lists it.
struct ControllerInfo {
  int index = 0;  ///< SDL device index: what --controller INDEX means
  std::string name;
  std::string guid;              ///< 32 hex digits
  bool game_controller = false;  ///< false: a plain joystick (numbered buttons, axes, hats)
  std::string path;              ///< its device node (what --controller PATH names); "" where SDL gives none
};

/// Initialises SDL's joystick, game-controller and event subsystems for as
/// long as it lives (reference-counted, so sessions may nest), with hints for
/// a program without a window: background events on, SDL's own SIGINT/SIGTERM
/// handlers off. Throws RuntimeError when SDL cannot start.
class SdlSession {
 public:
  SdlSession();
  ~SdlSession();
  SdlSession(const SdlSession&) = delete;
  SdlSession& operator=(const SdlSession&) = delete;
};

/// Adds the SDL mappings in a gamecontrollerdb.txt-style file (lines for other
/// platforms are skipped). Needs a live SdlSession. Throws InputError naming
/// FILE (unreadable) or FILE:LINE (a mapping SDL rejects, a line or the file
/// over kControllerDbLimits, more than 5,000 mappings for this platform),
/// ReadStopped when stop says so.
void load_controller_db(const std::string& path, const StopCheck& stop = {});

/// The live controller as an InputSource. Only the chosen controller feeds
/// the state (and the supervisor's, when one is chosen: its events carry
/// Pad::kSupervisor); the others are ignored. With a supervisor, each role is
/// bound to the pad it first connects and never takes a pad that may be the
/// other role's (pad_roles.hpp). A connect is followed by the
/// device's current state, all stamped with the connect's time, so that
/// buttons held when it appears are not presses.
class SdlInput final : public InputSource {
 public:
  /// Starts SDL and loads options.controller_db, asking stop while it reads
  /// (ReadStopped). Throws InputError for a bad selection (a supervisor's
  /// chosen as the operator's is, at supervisor_pos) or mapping file,
  /// RuntimeError when SDL cannot start. Opens no device yet: the first poll() does.
  explicit SdlInput(const SdlInputOptions& options, const StopCheck& stop = {});
  ~SdlInput() override;
  SdlInput(const SdlInput&) = delete;
  SdlInput& operator=(const SdlInput&) = delete;

  /// Drains SDL's queue without blocking and returns the chosen controllers'
  /// events since the last call, every one stamped now_ms (valid until the
  /// next call). Never throws.
  const std::vector<InputEvent>& poll(std::int64_t now_ms);

  void pump(TickInput& input, std::int64_t now_ms) override;
  [[nodiscard]] bool finished(std::int64_t /*now_ms*/) const override { return false; }
  [[nodiscard]] bool supervised() const override;

  /// Sets the chosen controller's light and starts its rumble (at the last
  /// poll's time; later pulses start from poll()). Nothing without a
  /// controller, or for what it lacks. Never blocks, never throws.
  void feedback(const FeedbackPattern& pattern) override;

  /// The chosen controller's inputs; none while it is not connected.
  [[nodiscard]] std::optional<DeviceLayout> device() const override;
  /// The operator's role's refusal, else the supervisor's (InputSource::refusal).
  [[nodiscard]] std::string refusal() const override;

  /// "the first controller", "controller 1", "controller named 'xbox'"...
  [[nodiscard]] std::string selection() const;
  /// The same for the supervisor's; empty without one.
  [[nodiscard]] std::string supervisor_selection() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The SDL input source for the run loop (an SdlInput).
std::unique_ptr<InputSource> make_sdl_input_source(const SdlInputOptions& options, const StopCheck& stop = {});

/// The devices attached now, in SDL device-index order. Starts its own
/// SdlSession and loads options.controller_db (so names reflect the mappings);
/// paths through options.places.
std::vector<ControllerInfo> list_controllers(const SdlInputOptions& options);

}  // namespace andros::input
