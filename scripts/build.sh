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
# The test binaries' precompiled header (tests/CMakeLists.txt) is cached only
# with these: ccache cannot see __TIME__ or __DATE__ through a precompiled
# header (nothing here uses them: -Wdate-time, from the package's flags, warns).
export CCACHE_SLOPPINESS=${CCACHE_SLOPPINESS:+$CCACHE_SLOPPINESS,}pch_defines,time_macros
build_dir=${BUILD_DIR:-build}
werror=OFF
[[ ${CI:-} == true ]] && werror=ON
# The flags (BUILD_FLAGS):
#   package (the default): the Debian package's own, from dpkg-buildflags as
#     debhelper passes them to CMake (debian/rules' DEB_BUILD_MAINT_OPTIONS,
#     and -g1 appended as scripts/package.sh does): -O2, the hardening flags
#     (stack protector, _FORTIFY_SOURCE, relro/now). The tests run the code the
#     package ships, and the package's build (into build/, as this one) finds
#     its objects in ccache instead of compiling them again.
#   cmake: CMake's RelWithDebInfo ("-O2 -g1 -DNDEBUG"), for a build that sets
#     its own (the sanitizer build: -DCMAKE_CXX_FLAGS_RELWITHDEBINFO=...); also
#     what a machine without dpkg-buildflags gets.
# -g1 (line tables: backtraces and sanitizer reports keep file:line) instead of
# full -g: the same code and warnings, a third less compile time on the
# template-heavy files.
flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_CXX_FLAGS=
       -DCMAKE_EXE_LINKER_FLAGS= -DCMAKE_SHARED_LINKER_FLAGS= -DCMAKE_MODULE_LINKER_FLAGS=)
if [[ ${BUILD_FLAGS:-package} == package ]] && command -v dpkg-buildflags >/dev/null; then
  deb_flags() {
    DEB_BUILD_MAINT_OPTIONS=$(sed -n 's/^export DEB_BUILD_MAINT_OPTIONS *= *//p' debian/rules) \
      DEB_CXXFLAGS_APPEND=-g1 dpkg-buildflags --get "$1"
  }
  ldflags=$(deb_flags LDFLAGS)
  flags=(-DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="$(deb_flags CXXFLAGS) $(deb_flags CPPFLAGS)"
         -DCMAKE_EXE_LINKER_FLAGS="$ldflags" -DCMAKE_SHARED_LINKER_FLAGS="$ldflags" -DCMAKE_MODULE_LINKER_FLAGS="$ldflags")
elif [[ ${BUILD_FLAGS:-package} != @(package|cmake) ]]; then
  echo "build.sh: BUILD_FLAGS is 'package' or 'cmake', not '$BUILD_FLAGS'" >&2
  exit 2
fi
cmake -S . -B "$build_dir" "${flags[@]}" -DANDROS_WERROR="$werror" -DANDROS_BUILD_TESTS=ON "$@" >/dev/null
targets=()
for t in ${BUILD_TARGETS:-}; do targets+=(--target "$t"); done
cmake --build "$build_dir" --parallel "$(nproc)" "${targets[@]}"
