#!/usr/bin/env bash
# The README's run command: installs what is missing, builds, and runs the
# bridge. Arguments go to `andros-bridge run`. With none, it plays the bundled
# demonstration drive (demos/drive.events, about 12 s) into the built-in
# simulated vehicle, so that a fresh clone shows the whole path working with
# no controller and no hardware. For a live controller: scripts/run.sh --input sdl
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
bin=${BUILD_DIR:-build}/src/andros-bridge
(($# > 0)) || set -- --input demos/drive.events
exec "$bin" run "$@"
