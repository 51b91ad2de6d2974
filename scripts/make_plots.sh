#!/usr/bin/env bash
# Writes the plot of the bundled demo drive: docs/plots/drive.svg, the HD1
# mapping replaying demos/drive.events (docs/recording.md). Reads the mapping
# file directly (--mapping) so that a user's own mapping in ~/.config cannot
# end up in it. tests/cli/test_plot.sh runs it into a temporary folder and
# fails when the shipped plot differs.
#   scripts/make_plots.sh [BIN [OUT_DIR]]   (defaults: build/src/andros-bridge docs/plots)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/src/andros-bridge}
out=${2:-$root/docs/plots}
mkdir -p "$out"
"$bin" plot "$root/demos/drive.events" --mapping "$root/mappings/hd1.yaml" --output "$out/drive.svg"
