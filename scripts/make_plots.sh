#!/usr/bin/env bash
# Writes the plots of the bundled demo drives (docs/recording.md):
# docs/plots/drive.svg, the HD1 mapping replaying demos/drive.events, and
# docs/plots/supervised.svg, mappings/examples/supervisor.yaml (HD1 with a supervisor's
# controller) replaying demos/supervised.events with weapons enabled. Reads
# the mapping files directly (--mapping), with XDG_CONFIG_HOME an empty
# folder (the example's `extends: hd1` finds the tree's), so that a user's own
# mapping in ~/.config cannot end up in them. tests/cli/test_plot.sh runs it into a temporary folder and
# fails when the shipped plot differs.
#   scripts/make_plots.sh [BIN [OUT_DIR]]   (defaults: build/src/andros-bridge docs/plots)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/src/andros-bridge}
out=${2:-$root/docs/plots}
mkdir -p "$out"
XDG_CONFIG_HOME=$(mktemp -d)
export XDG_CONFIG_HOME
trap 'rmdir "$XDG_CONFIG_HOME"' EXIT
"$bin" plot "$root/demos/drive.events" --mapping "$root/mappings/hd1.yaml" --output "$out/drive.svg"
"$bin" plot "$root/demos/supervised.events" --mapping "$root/mappings/examples/supervisor.yaml" --weapons \
  --output "$out/supervised.svg"
