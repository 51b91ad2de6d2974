#!/usr/bin/env bash
# The README's run command: installs what is missing, builds, and runs the
# bridge into the built-in simulated vehicle (or wherever the arguments say).
# Arguments go to `andros-bridge run`. With none: a connected controller drives
# the simulated vehicle (hold LB, press it again after connecting); with no
# controller attached, the bundled demonstration drive (demos/drive.events,
# about 12 s) plays instead, so a fresh clone shows the whole path working
# with no controller and no hardware.
set -euo pipefail
cd "$(dirname "$0")/.."
# Only what `run` needs: the tests are scripts/test.sh's to build.
BUILD_TARGETS=andros-bridge scripts/build.sh
bin=${BUILD_DIR:-build}/src/andros-bridge
if (($# == 0)); then
  if [[ -n $("$bin" controllers --json 2>/dev/null) ]]; then
    echo "run.sh: driving the simulated vehicle with your controller (hold LB; Ctrl-C to stop)" >&2
    set -- --input sdl
  else
    echo "run.sh: no controller attached: playing demos/drive.events into the simulated vehicle" >&2
    echo "run.sh: plug in a gamepad and run again, or see 'scripts/run.sh --help'" >&2
    set -- --input demos/drive.events
  fi
fi
exec "$bin" run "$@"
