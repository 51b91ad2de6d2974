#!/usr/bin/env bash
# The stage check (cmake/check_layers.cmake, docs/architecture.md) passes on
# the tree and fails, naming the file, on a copy with one upward include.
set -euo pipefail
root=${1:?usage: test_layers.sh SOURCE_ROOT}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

cmake -DROOT="$root" -P "$root/cmake/check_layers.cmake" || fail "the tree itself breaks the stage order"

copy() {
  rm -rf "$work/tree"
  mkdir -p "$work/tree"
  cp -r "$root/include" "$root/src" "$root/cmake" "$work/tree/"
}
expect_refused() {  # FILE INCLUDE-LINE WHAT
  copy
  printf '%s\n' "$2" >>"$work/tree/$1"
  if cmake -DROOT="$work/tree" -P "$work/tree/cmake/check_layers.cmake" >"$work/out" 2>&1; then
    fail "$3 was not refused"
  fi
  grep -q "$1" "$work/out" || fail "$3: the message does not name $1: $(cat "$work/out")"
}
expect_refused include/andros/protocol/frame.hpp '#include "andros/mapping/engine.hpp"' "protocol including mapping"
expect_refused src/base/text.cpp '#include "andros/cli/config.hpp"' "base including cli"
expect_refused src/run/bridge.cpp '#include "andros/view/operator_screens.hpp"' "run including view"
expect_refused src/run/bridge.cpp '#include "andros/record/session.hpp"' "run including record"
expect_refused include/andros/record/session.hpp '#include "andros/view/plot.hpp"' "record including view"
expect_refused src/link/tcp_link.cpp '#include "andros/io/link.hpp"' "an include outside the stage folders"

# Same-stage and downward includes stay allowed.
copy
printf '%s\n' '#include "andros/base/error.hpp"' '#include "andros/view/operator_screens.hpp"' >>"$work/tree/src/cli/main.cpp"
cmake -DROOT="$work/tree" -P "$work/tree/cmake/check_layers.cmake" || fail "a downward include was refused"
echo "stage order checks: ok"
