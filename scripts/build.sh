#!/usr/bin/env bash
# Installs what is missing, then configures and builds into $BUILD_DIR (default build/):
# every target, or only $BUILD_TARGETS (e.g. BUILD_TARGETS=andros-bridge).
# Arguments go to cmake's configure step. In CI (CI=true) warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
# ccache (CMakeLists.txt uses it when installed) keys on paths relative to the
# tree, so that another clone of it, or a worktree, finds the same objects.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
build_dir=${BUILD_DIR:-build}
werror=OFF
[[ ${CI:-} == true ]] && werror=ON
# -g1 (line tables: backtraces and sanitizer reports keep file:line) instead of
# full -g: the same -O2 code and warnings, a third less compile time on the
# template-heavy files, which keeps CI well inside its budget on 2 cores.
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DANDROS_WERROR="$werror" -DANDROS_BUILD_TESTS=ON "$@" >/dev/null
targets=()
for t in ${BUILD_TARGETS:-}; do targets+=(--target "$t"); done
cmake --build "$build_dir" --parallel "$(nproc)" "${targets[@]}"
