#!/usr/bin/env bash
# Checks the Debian package scripts/package.sh built (docs/testing.md):
# lintian reports no error, its files are exactly tests/package/contents.txt,
# the unit passes `systemd-analyze verify`, and the packaged binary, unpacked
# with dpkg-deb -x, finds its own mappings and drives the simulated vehicle.
#   tests/package/test_package.sh DEB
set -uo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
DEB=$1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# lintian: errors fail; warnings are listed (docs/testing.md says which are expected and why).
"$HERE/../../scripts/setup.sh" lintian systemd  # systemd: systemd-analyze, run offline
lintian --tag-display-limit 0 "$DEB" >"$TMP/lintian" 2>&1
cat "$TMP/lintian"
grep -q '^E: ' "$TMP/lintian" && fail "lintian reports errors"

# The contents, as paths (directories end in /), against the checked-in list.
dpkg-deb -c "$DEB" | awk '{print $6}' | sed 's|^\./|/|' | grep -v '^/$' | LC_ALL=C sort >"$TMP/contents"
if ! diff -u "$HERE/contents.txt" "$TMP/contents" >"$TMP/contents.diff"; then
  fail "package contents differ from tests/package/contents.txt: $(cat "$TMP/contents.diff")"
fi
dpkg-deb -f "$DEB" Depends | grep -q 'libsdl2' || fail "Depends has no libsdl2 (shlibdeps): $(dpkg-deb -f "$DEB" Depends)"
dpkg-deb --ctrl-tarfile "$DEB" | tar -xO ./conffiles 2>/dev/null | grep -qx /etc/andros-bridge/andros-bridge.conf ||
  fail "/etc/andros-bridge/andros-bridge.conf is not a conffile"

# The unpacked tree: the binary, its mappings beside it (not the source tree's).
ROOT=$TMP/root
dpkg-deb -x "$DEB" "$ROOT"
BIN=$ROOT/usr/bin/andros-bridge
export XDG_CONFIG_HOME=$TMP/xdg
"$BIN" --version | grep -q '^andros-bridge ' || fail "--version"
"$BIN" check "$ROOT"/usr/share/andros-bridge/mappings/*.yaml >"$TMP/check" 2>&1 || fail "check: $(cat "$TMP/check")"
"$BIN" run --config "$ROOT/etc/andros-bridge/andros-bridge.conf" --port sim \
  --input "$ROOT/usr/share/andros-bridge/demos/drive.events" >/dev/null 2>"$TMP/run"
code=$?
[[ $code -eq 0 ]] || fail "run into sim exited $code: $(cat "$TMP/run")"
grep -q "^info: robot HD1, mapping $ROOT/usr/share/andros-bridge/mappings/hd1.yaml, port sim, code 01$" "$TMP/run" ||
  fail "the packaged binary did not load its own mapping: $(grep mapping "$TMP/run")"
grep -Eq "sim vehicle decoded [0-9]{3,} frames: ([0-9]+) valid, 0 bad checksum, 0 invalid" "$TMP/run" ||
  fail "the sim vehicle did not decode the demo's frames: $(tail -2 "$TMP/run")"

# The unit, as systemd reads it (offline: no systemd is running here), with
# ExecStart pointed at the unpacked binary; and its exposure.
unit=$(find "$ROOT" -name andros-bridge.service)
[[ -n $unit ]] || fail "no andros-bridge.service in the package"
if [[ -n $unit ]]; then
  sed "s|/usr/bin/andros-bridge|$BIN|" "$unit" >"$TMP/andros-bridge.service"
  systemd-analyze verify --man=no "$TMP/andros-bridge.service" >"$TMP/verify" 2>&1 ||
    fail "systemd-analyze verify: $(cat "$TMP/verify")"
  systemd-analyze security --offline=true --no-pager "$TMP/andros-bridge.service" 2>/dev/null |
    grep 'Overall exposure' | sed "s|$TMP/||"
fi

if ((failures)); then echo "package: $failures check(s) failed" >&2; exit 1; fi
echo "package: all checks passed"
