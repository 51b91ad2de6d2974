// LD_PRELOAD=libandros_bench_virtual_pad.so: SDL's virtual game controller
// attached inside a process that is not ours (`andros-bridge run --input
// sdl`), as soon as that process starts SDL's joystick support, so that the
// idle-cost benchmark measures the real run with a controller connected and
// at rest, on a machine with no gamepad. It wraps SDL_InitSubSystem; nothing
// else changes.
#include <SDL.h>
#include <dlfcn.h>

namespace {

using InitSubSystem = int (*)(Uint32);

bool attached = false;

void attach_pad() {
  SDL_VirtualJoystickDesc desc;
  SDL_zero(desc);
  desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
  desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
  desc.naxes = SDL_CONTROLLER_AXIS_MAX;
  desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
  desc.name = "Bench Pad";
  attached = SDL_JoystickAttachVirtualEx(&desc) >= 0;
}

}  // namespace

extern "C" int SDL_InitSubSystem(Uint32 flags) {
  static const auto real = reinterpret_cast<InitSubSystem>(dlsym(RTLD_NEXT, "SDL_InitSubSystem"));
  if (real == nullptr) return -1;
  const int result = real(flags);
  if (result == 0 && !attached && (flags & SDL_INIT_JOYSTICK) != 0) attach_pad();
  return result;
}
