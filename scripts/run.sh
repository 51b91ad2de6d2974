#!/usr/bin/env bash
# The README's run command: installs what is missing, builds, and runs the bridge.
# Arguments go to `andros-bridge run`.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
bin=${BUILD_DIR:-build}/src/andros-bridge
if "$bin" run --help >/dev/null 2>&1; then
  exec "$bin" run "$@"
fi
# Until the live bridge lands: show the commands and decode the ICD's worked example.
"$bin" --help
echo
echo "Decoding the ICD's worked example frame:"
"$bin" frame encode --raw 00001C2000907F7E3E0000FFFF20CC02 | "$bin" frame decode -
