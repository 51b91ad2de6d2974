#!/usr/bin/env bash
# Installs what is missing, then configures and builds into $BUILD_DIR (default build/).
# In CI (CI=true) warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build_dir=${BUILD_DIR:-build}
werror=OFF
[[ ${CI:-} == true ]] && werror=ON
# -g1 (line tables: backtraces and sanitizer reports keep file:line) instead of
# full -g: the same -O2 code and warnings, a third less compile time on the
# template-heavy files, which keeps CI well inside its budget on 2 cores.
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DANDROS_WERROR="$werror" -DANDROS_BUILD_TESTS=ON "$@" >/dev/null
cmake --build "$build_dir" --parallel "$(nproc)"
