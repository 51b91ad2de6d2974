#!/usr/bin/env bash
# The service under a real systemd (docs/testing.md, "The service under
# systemd"): boots a throwaway container, systemd-nspawn -b, whose root is an
# overlay of this machine's own / with a tmpfs upper layer (nothing written
# inside survives), and runs tests/service/systemd_checks.sh in it on DEB.
#   tests/service/test_systemd.sh DEB
# Prints "systemd: skipped (WHY)" and exits 0 where no container can be booted
# (not root, no systemd-nspawn, no mount namespace or overlay); exits 1 if a
# check failed or the container did not boot.
#
# Nothing is left behind on the host: the tmpfs, the overlay and a tmpfs over
# /run (where nspawn keeps its own state) are mounted in a private mount
# namespace (unshare) that ends with the container; nspawn runs in a cgroup of
# its own, removed at the end; the exit trap ends the container whatever
# happened (SIGTERM to nspawn: the container's systemd shuts down; then
# SIGKILL to the container's PID 1, which ends its every process).
set -uo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
DEB=$(realpath "$1")
skip() { echo "systemd: skipped ($*)"; exit 0; }

[[ $(id -u) == 0 ]] || skip "not root: booting a container needs root"
command -v systemd-nspawn >/dev/null || skip "no systemd-nspawn (Debian package systemd-container)"
[[ -x /lib/systemd/systemd ]] || skip "no /lib/systemd/systemd to boot"
unshare --mount --propagation private true 2>/dev/null || skip "no mount namespaces here"

TMP=$(mktemp -d /tmp/andros-systemd.XXXXXX)
name=andros-test-$$
nspawn_pid='' cgroups=()
cleanup() {
  if [[ -n $nspawn_pid ]] && kill -0 "$nspawn_pid" 2>/dev/null; then
    local init=
    read -r init _ 2>/dev/null <"/proc/$nspawn_pid/task/$nspawn_pid/children"
    kill -TERM "$nspawn_pid" 2>/dev/null
    for _ in $(seq 100); do kill -0 "$nspawn_pid" 2>/dev/null || break; sleep 0.1; done
    for p in $init $nspawn_pid; do kill -KILL "$p" 2>/dev/null; done
  fi
  wait 2>/dev/null
  # Deepest first: the container's systemd made its own cgroups under ours.
  local cg
  for cg in "${cgroups[@]}"; do
    for _ in $(seq 50); do
      find "$cg" -depth -type d -exec rmdir {} + 2>/dev/null
      [[ -d $cg ]] || break
      sleep 0.1
    done
    [[ -d $cg ]] && echo "systemd: could not remove the cgroup $cg" >&2
  done
  rm -rf "$TMP"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP  # the cleanup on a signal too

# A cgroup of our own in each hierarchy systemd uses (the named v1 one and/or
# cgroup2), so that nspawn (--keep-unit: no service manager on the host to ask)
# puts its payload and supervisor cgroups there, apart from any other container.
while IFS=: read -r _ controllers path; do
  case $controllers in
    name=systemd) type=cgroup opt=name=systemd ;;
    "") type=cgroup2 opt= ;;
    *) continue ;;
  esac
  mnt=$(awk -v t="$type" -v o="$opt" '$3 == t && (o == "" || $4 ~ o) { print $2; exit }' /proc/mounts)
  [[ -n $mnt ]] || continue
  mkdir "$mnt${path%/}/$name" 2>/dev/null || skip "cannot make a cgroup in $mnt${path%/}"
  cgroups+=("$mnt${path%/}/$name")
done </proc/self/cgroup
((${#cgroups[@]})) || skip "no systemd or cgroup2 hierarchy mounted"

# What the container sees of this run, read-only: the package and the checks.
mkdir -p "$TMP/share" "$TMP/root"
cp "$DEB" "$TMP/share/andros-bridge.deb"
cp "$HERE/systemd_checks.sh" "$HERE/port_capture.py" "$HERE/../cli/check_frames.py" "$TMP/share/"

# The container: booted to basic.target (no getty, no other package's
# services), no network but its own loopback, its journal its own. setsid:
# a terminal's Ctrl-C reaches this script (whose trap ends the container),
# not nspawn; it does not fork here (a script's background job leads no
# process group), so $! is nspawn's PID.
start=$SECONDS
setsid unshare --mount --propagation private bash -c '
  set -e
  for cg in "${@:3}"; do echo $$ >"$cg/cgroup.procs"; done
  mount -t tmpfs -o size=1g,mode=0755 andros-overlay "$1"
  mkdir "$1/upper" "$1/work" "$1/root"
  mount -t overlay andros-overlay -o "lowerdir=/,upperdir=$1/upper,workdir=$1/work" "$1/root"
  mount -t tmpfs -o mode=0755 andros-run /run
  exec systemd-nspawn --quiet --directory="$1/root" --boot --machine="$2" --register=no --keep-unit \
    --link-journal=no --private-network --console=read-only --bind-ro="$1/../share:/mnt/andros-test" \
    systemd.unit=basic.target' bash "$TMP/root" "$name" "${cgroups[@]}" </dev/null >"$TMP/boot.log" 2>&1 &
nspawn_pid=$!
# The container's PID 1 is nspawn's child (nspawn is exec'd in place of the
# shell), at most 30 s.
init=
for _ in $(seq 300); do
  read -r init _ 2>/dev/null <"/proc/$nspawn_pid/task/$nspawn_pid/children" || true
  # Its manager's socket up: systemctl can ask it.
  [[ $(cat "/proc/${init:-0}/comm" 2>/dev/null) == systemd ]] &&
    nsenter --target "$init" --mount test -S /run/systemd/private 2>/dev/null && break
  kill -0 "$nspawn_pid" 2>/dev/null || break
  init=
  sleep 0.1
done
inside() { nsenter --target "$init" --all -- env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 "$@"; }
# Booted: "running", or "degraded" (a unit of the host's own failed in here:
# listed, and no concern of the service's).
state=$([[ -n $init ]] && timeout 60 nsenter --target "$init" --all -- systemctl is-system-running --wait)
if [[ $state != running && $state != degraded ]]; then
  grep -Ev '^\s*$' "$TMP/boot.log" | tail -20
  echo "systemd: FAILED: the container did not boot (${state:-no systemd})"
  exit 1
fi
echo "systemd: container booted in $((SECONDS - start)) s ($(inside systemctl --version | head -1); $state)"
[[ $state == degraded ]] && inside systemctl --failed --no-pager --no-legend
# Each of its waits is bounded; this bounds them all (a hang is a failure).
# In the background, waited for: a signal to this script is handled at once.
inside timeout 300 bash /mnt/andros-test/systemd_checks.sh /mnt/andros-test/andros-bridge.deb \
  /mnt/andros-test/check_frames.py &
wait $!
status=$?
echo "systemd: $( ((status == 0)) && echo "all checks passed" || echo "FAILED") in $((SECONDS - start)) s"
exit $status
