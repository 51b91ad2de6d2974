#!/usr/bin/env bash
# Writes the cheat sheets of the shipped robot layouts: docs/sheets/<robot>.svg
# and .txt, one pair per mappings/<robot>.yaml (common.yaml is a base, not a
# robot). Reads the files directly (--mapping) so that a user's own mapping in
# ~/.config cannot end up in the shipped sheets. tests/cli/test_sheet.sh runs
# it into a temporary folder and fails when a shipped sheet differs.
#   scripts/make_sheets.sh [BIN [OUT_DIR]]   (defaults: build/src/andros-bridge docs/sheets)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/src/andros-bridge}
out=${2:-$root/docs/sheets}
mkdir -p "$out"
for mapping in "$root"/mappings/*.yaml; do
  robot=$(basename "$mapping" .yaml)
  [[ $robot == common ]] && continue
  "$bin" sheet --mapping "$mapping" --format svg --output "$out/$robot.svg"
  "$bin" sheet --mapping "$mapping" --format text --output "$out/$robot.txt"
done
