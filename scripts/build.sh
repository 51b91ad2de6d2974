#!/usr/bin/env bash
# Installs what is missing, then configures and builds into $BUILD_DIR (default build/).
# In CI (CI=true) warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build_dir=${BUILD_DIR:-build}
werror=OFF
[[ ${CI:-} == true ]] && werror=ON
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DANDROS_WERROR="$werror" -DANDROS_BUILD_TESTS=ON "$@" >/dev/null
cmake --build "$build_dir" --parallel "$(nproc)"
