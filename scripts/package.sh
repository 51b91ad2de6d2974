#!/usr/bin/env bash
# Builds the Debian package (debian/, dpkg-buildpackage -b -us -uc) and puts
# it in dist/: dist/andros-bridge_VERSION_ARCH.deb. Installs what the build
# needs with apt-get (as root, or through sudo), as scripts/setup.sh does.
# The build runs on a copy of the tree in build-deb/, so the work tree stays
# clean. Install with: sudo apt install ./dist/andros-bridge_*.deb
set -euo pipefail
cd "$(dirname "$0")/.."
as_root=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "package: need root or sudo to install build dependencies" >&2; exit 1; }
  as_root=(sudo)
fi

scripts/setup.sh dpkg-dev debhelper fakeroot
if ! dpkg-checkbuilddeps >/dev/null 2>&1; then
  echo "package: installing the build dependencies of debian/control"
  "${as_root[@]}" apt-get update -qq
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get build-dep -y -qq --no-install-recommends ./
fi

work=build-deb
rm -rf "$work" && mkdir -p dist
# A copy of the tree's files (scripts/copy_source.sh: a list of them, so
# that the jobs writing into the tree beside this one cannot fail the copy).
scripts/copy_source.sh . "$work/src"
# parallel: every core; noautodbgsym: no -dbgsym package (nothing ships it),
# so the debug information is stripped and thrown away: -g1 instead of -g
# (DEB_CXXFLAGS_APPEND, after dpkg-buildflags' -g) compiles in less time;
# nocheck: the package builds no tests (scripts/test.sh ran them).
# ccache: debhelper gives the build a HOME of its own, so the cache is named.
if command -v ccache >/dev/null; then
  export CCACHE_DIR=${CCACHE_DIR:-$(ccache -k cache_dir)} CCACHE_BASEDIR="$PWD/$work/src"
fi
# CI=true: warnings are errors here too (debian/rules reads ANDROS_WERROR).
[[ ${CI:-} == true ]] && export ANDROS_WERROR=ON
(cd "$work/src" && DEB_BUILD_OPTIONS="parallel=$(nproc) noautodbgsym nocheck ${DEB_BUILD_OPTIONS:-}" \
  DEB_CXXFLAGS_APPEND="-g1 ${DEB_CXXFLAGS_APPEND:-}" dpkg-buildpackage -b -us -uc)
rm -f dist/andros-bridge_*.deb
mv "$work"/andros-bridge_*.deb dist/
rm -rf "$work"
echo "package: $(ls dist/andros-bridge_*.deb)"
