#!/usr/bin/env bash
# The README's run command: installs what is missing, builds, and runs the
# bridge into the built-in simulated vehicle (or wherever the arguments say).
# Arguments go to `andros-bridge run`. With none: the trainer (docs/trainer.md),
# the simulated vehicle on a local web page whose address it prints: a
# connected controller drives it (hold LB, press it again after connecting);
# with no controller attached, the bundled demonstration drive
# (demos/drive.events, about 12 s) plays instead, and the page stays up until
# Ctrl-C, so a fresh clone shows the whole path working with no controller and
# no hardware.
set -euo pipefail
cd "$(dirname "$0")/.."
# Only what `run` needs: the tests are scripts/test.sh's to build.
BUILD_TARGETS=andros-bridge scripts/build.sh
bin=${BUILD_DIR:-build}/src/andros-bridge
if (($# == 0)); then
  echo "run.sh: the trainer: open http://127.0.0.1:8037/ in a browser to see the simulated vehicle" >&2
  if [[ -n $("$bin" controllers --json 2>/dev/null) ]]; then
    echo "run.sh: driving the simulated vehicle with your controller (hold LB; Ctrl-C to stop)" >&2
    exec "$bin" trainer --input sdl
  fi
  echo "run.sh: no controller attached: playing demos/drive.events into the trainer (Ctrl-C to stop)" >&2
  echo "run.sh: plug in a gamepad and run again, or see 'scripts/run.sh --help'" >&2
  exec "$bin" trainer --input demos/drive.events
fi
exec "$bin" run "$@"
