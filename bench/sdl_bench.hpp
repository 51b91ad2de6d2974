#pragma once
// What the SDL benchmarks share: a virtual pad, percentiles. The clock and
// absolute sleeps are base's (andros/base/clock.hpp).

#include <SDL.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "andros/base/clock.hpp"
#include "andros/input/sdl_input.hpp"

namespace andros::bench {

/// A virtual game controller, opened so that the benchmark can move it.
inline SDL_Joystick* attach_virtual_pad() {
  SDL_VirtualJoystickDesc desc;
  SDL_zero(desc);
  desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
  desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
  desc.naxes = SDL_CONTROLLER_AXIS_MAX;
  desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
  desc.name = "Bench Pad";
  SDL_Joystick* joy = SDL_JoystickOpen(SDL_JoystickAttachVirtualEx(&desc));
  if (joy == nullptr) {
    std::fprintf(stderr, "cannot attach a virtual pad: %s\n", SDL_GetError());
    std::exit(1);
  }
  return joy;
}

/// SDL started headless, the input source, and a virtual pad to move.
struct PadRig {
  PadRig() : input((setenv("SDL_VIDEODRIVER", "dummy", 0), input::SdlInputOptions{})), pad(attach_virtual_pad()) {
    spdlog::set_level(spdlog::level::err);  // keep the table clean
  }
  ~PadRig() {
    if (pad != nullptr) SDL_JoystickClose(pad);
  }
  PadRig(const PadRig&) = delete;
  PadRig& operator=(const PadRig&) = delete;

  input::SdlInput input;
  SDL_Joystick* pad;
};

/// The q-quantile (0..1) of values, in the values' unit.
inline double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const auto i = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5);
  return values[std::min(i, values.size() - 1)];
}

}  // namespace andros::bench
