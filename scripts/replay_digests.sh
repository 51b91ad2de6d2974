#!/usr/bin/env bash
# Prints one line per (mapping, script, options) case: the sha256 of what
# `replay` wrote to stdout, then its exit code. Run it before and after a
# change that must not change behaviour and compare the two outputs:
#   scripts/replay_digests.sh build/src/andros-bridge > before.txt
#   ... change, rebuild ...
#   scripts/replay_digests.sh build/src/andros-bridge | diff before.txt -
# Every shipped mapping and every test mapping, against every event script in
# the repository (demos and test data), in hex and jsonl, weapons off and on.
set -u
bin=${1:?usage: replay_digests.sh ANDROS_BRIDGE_BINARY}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
mapfile -t scripts < <(find demos tests/data -name '*.events' | LC_ALL=C sort)
mapfile -t maps < <(ls mappings/*.yaml tests/data/mappings/*.yaml | LC_ALL=C sort)
for map in "${maps[@]}"; do
  for script in "${scripts[@]}"; do
    for opts in "--format hex" "--format jsonl" "--format hex --weapons"; do
      # shellcheck disable=SC2086
      "$bin" replay --mapping "$map" $opts "$script" >"$out" 2>/dev/null
      rc=$?
      printf '%s %s %s %s rc=%s\n' "$map" "$script" "${opts// /_}" "$(sha256sum <"$out" | cut -c1-16)" "$rc"
    done
  done
done
