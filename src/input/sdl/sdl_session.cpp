// SDL's lifetime, extra mappings, and the device list.
#include <SDL.h>
#include <spdlog/spdlog.h>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "andros/input/sdl_input.hpp"
#include "controller_selection.hpp"
#include "pad_facts.hpp"

namespace andros::input {
namespace {

constexpr Uint32 kSdlSubsystems = SDL_INIT_EVENTS | SDL_INIT_JOYSTICK | SDL_INIT_GAMECONTROLLER;

/// The most mappings a controller database may add. SDL keeps them in a
/// list that each SDL_GameControllerAddMapping walks end to end (to find the
/// controller's GUID, then to append): n mappings cost n*n/2 steps, and the
/// 86,596 lines that fit the file limit took 96 s of CPU. The community
/// gamecontrollerdb.txt has a few thousand lines for all platforms together
/// (only this platform's are added); 5,000 take a tenth of a second.
constexpr int kMaxControllerMappings = 5000;

}  // namespace

SdlSession::SdlSession() {
  // There is no window: without this SDL drops controller events as
  // "background" input.
  SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
  // SIGINT/SIGTERM belong to the program (neutral frames, then exit), not to
  // SDL, which would turn them into an SDL_QUIT event nobody reads.
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  if (SDL_InitSubSystem(kSdlSubsystems) != 0) {
    throw RuntimeError(std::string("cannot start SDL's controller support: ") + SDL_GetError());
  }
}

SdlSession::~SdlSession() {
  SDL_QuitSubSystem(kSdlSubsystems);
  if (SDL_WasInit(SDL_INIT_EVERYTHING) == 0) SDL_Quit();
}

void load_controller_db(const std::string& path, const StopCheck& stop) {
  auto in = TextReader::open(path, kControllerDbLimits, stop);
  // Line by line rather than SDL_GameControllerAddMappingsFromFile, which
  // skips bad lines silently: a mapping the operator wrote should either load
  // or be named.
  const std::string platform = std::string("platform:") + SDL_GetPlatform();
  int added = 0;
  while (const auto raw = in.next_line()) {
    const std::string line(trim(*raw));
    if (line.empty() || line[0] == '#') continue;
    const auto at = line.find("platform:");
    if (at != std::string::npos && line.compare(at, platform.size(), platform) != 0) continue;
    if (added == kMaxControllerMappings) {
      throw InputError(SourcePos{path, in.line_number(), 1},
                       "more than " + std::to_string(kMaxControllerMappings) + " controller mappings for " +
                           SDL_GetPlatform() + " (SDL's time to add them grows with the square of their number): " +
                           "keep the lines of the controllers you use");
    }
    if (SDL_GameControllerAddMapping(line.c_str()) < 0) {
      throw InputError(SourcePos{path, in.line_number(), 1}, std::string("bad SDL mapping: ") + SDL_GetError());
    }
    ++added;
  }
  spdlog::debug("{}: {} controller mapping(s) for {}", path, added, SDL_GetPlatform());
}

std::vector<ControllerInfo> list_controllers(const SdlInputOptions& options) {
  const SdlSession session;
  if (!options.controller_db.empty()) load_controller_db(options.controller_db);
  SDL_PumpEvents();  // lets drivers that enumerate lazily report what they found
  std::vector<ControllerInfo> list;
  for (const auto& pad : PadReader(options.places).attached()) {
    list.push_back(
        ControllerInfo{pad.index, pad.name, pad.guid, SDL_IsGameController(pad.index) == SDL_TRUE, pad.path});
  }
  return list;
}

}  // namespace andros::input
