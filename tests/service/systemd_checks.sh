#!/usr/bin/env bash
# The checks of the systemd phase, run INSIDE the throwaway container that
# tests/service/test_systemd.sh boots (its own systemd as PID 1, no udev):
# the package installed, the service started, supervised, reloaded, stopped,
# enabled, upgraded and removed (docs/testing.md, "The service under systemd").
#   systemd_checks.sh DEB CHECK_FRAMES_PY
# Prints "ok: ..." or "FAIL: ..." per check; exits 1 if any failed. Every
# wait is bounded; each time limit the issue sets (READY within 5 s, stop
# within 2 s) is measured between the timestamps systemd recorded, not from
# when this script acted, so that a loaded host cannot make a verdict lie.
set -uo pipefail
DEB=$1 CHECK_FRAMES=$2
HERE=$(cd "$(dirname "$0")" && pwd)
UNIT=andros-bridge.service
CONF=/etc/andros-bridge/andros-bridge.conf
T=/run/andros-test
PORT=$T/port CAPTURE=$T/capture
failures=0
ok() { echo "ok: $*"; }
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
check() { local what=$1; shift; if "$@"; then ok "$what"; else fail "$what"; return 1; fi; }
# need WHAT CMD...: a check the ones after it stand on: failed, the script ends here.
need() { check "$@" || { finish; exit 1; }; }
prop() { systemctl show -P "$1" "$UNIT"; }
now_us() { python3 -c 'import time; print(time.monotonic_ns() // 1000)'; }  # systemd's *Monotonic clock
past_us() { (($(now_us) > $1)); }
status_has() { grep -Eq "$1" <<<"$(prop StatusText)"; }
# wait_for SECONDS CMD...: until CMD succeeds, at most SECONDS (a bound, never a verdict).
wait_for() {
  local end=$((SECONDS + $1))
  shift
  until "$@"; do ((SECONDS < end)) || return 1; sleep 0.1; done
}
frames() { andros-bridge frame decode "$CAPTURE" 2>/dev/null; }
driving_now() { frames | tail -1 | python3 -c 'import json,sys; l=sys.stdin.read(); sys.exit(not l or json.loads(l)["signals"]["drive"] == 128)'; }
finish() {
  ((failures == 0)) && return 0
  echo "--- the journal of $UNIT"
  journalctl -u "$UNIT" --no-pager -o short-monotonic | tail -40
  return 1
}

mkdir -p "$T"
# The event script the service plays (config `input=`): the deadman held and
# the drive stick forward from 0.2 s for ten minutes, so that the bridge is
# driving whenever the run is not in a reload's neutral stretch.
printf '%s\n' '0 connect Test pad' '100 button leftshoulder 1' '200 axis lefty -32768' '600000 end' >"$T/drive.events"
config() { printf 'serialport=%s\ninput=%s\nrobot=%s\n%s' "$PORT" "$T/drive.events" "$1" "${2:-}" >"$CONF"; }

# 1. No `input` group here (no udev): the package must create it (its sysusers.d file).
# A host that has the package installed lends it to the overlay: purged
# here first, so that the install below is a first one.
if dpkg-query -W andros-bridge >/dev/null 2>&1; then dpkg --purge andros-bridge >/dev/null; fi
if getent group input >/dev/null; then groupdel input; fi
rm -f /var/lib/man-db/auto-update  # no man-db trigger run on each install (seconds)
# A container image's policy-rc.d ("exit 101": start no service while an
# image is built) would stop the package's scripts from starting, restarting
# and stopping the unit; a booted system has none.
rm -f /usr/sbin/policy-rc.d
check "no input group before the install (a system without udev)" bash -c '! getent group input >/dev/null'
dpkg -i "$DEB" >"$T/dpkg.log" 2>&1 || cat "$T/dpkg.log"
installed() { test "$(dpkg-query -W -f='${Status}' andros-bridge 2>/dev/null)" = "install ok installed"; }
need "dpkg -i installs the package" installed
check "the package created the input group" getent group input
check "installed, not enabled" test "$(systemctl is-enabled "$UNIT" 2>&1)" = disabled
check "installed, not started" test "$(prop ActiveState)" = inactive

# 2. Start: READY (Type=notify) within 5 s of the process's start, as systemd recorded both.
# The port's unit is ordered before the bridge's, which, so referenced, stays
# loaded once stopped (systemd unloads an inactive unit nothing refers to, and
# with it its record of the last run: the timestamps and exit status below).
systemd-run --quiet --unit=andros-test-port -p Before="$UNIT" python3 "$HERE/port_capture.py" "$PORT" "$CAPTURE"
wait_for 10 test -L "$PORT" || fail "the capture's port never appeared"
config HD1
need "systemctl start" systemctl start "$UNIT"
start_us=$(prop ExecMainStartTimestampMonotonic) ready_us=$(prop ActiveEnterTimestampMonotonic)
echo "   READY $(((ready_us - start_us) / 1000)) ms after the process started"
check "READY within 5 s of the start" test "$start_us" -gt 0 -a "$ready_us" -ge "$start_us" -a $((ready_us - start_us)) -le 5000000
wait_for 10 status_has '^HD1; enabled'
status=$(prop StatusText)
echo "   STATUS: $status"
check "STATUS= says the robot, the operating state, the link and the rate" \
  grep -Eq "^HD1; enabled[^;]*; link ${PORT}[^;]*: up; 25 Hz" <<<"$status"

# 3. The watchdog: pinged (systemd's record of the last ping moves on), nothing restarted 5 s after READY.
pid=$(prop MainPID)
need "running (pid $pid)" test "$pid" -gt 0
check "WatchdogSec=1s" test "$(prop WatchdogUSec)" = 1s
ping1=$(prop WatchdogTimestampMonotonic)
wait_for 30 past_us $((ready_us + 5000000))
ping2=$(prop WatchdogTimestampMonotonic)
check "the watchdog is pinged (last ping ${ping1} -> ${ping2} us)" test "$ping2" -gt "$ping1"
check "5 s after READY: NRestarts 0, the same process, active" \
  test "$(prop NRestarts)/$(prop MainPID)/$(prop ActiveState)" = "0/$pid/active"

# 4. Reload with a good config: the same process, the new robot in STATUS=.
config F6A
check "systemctl reload (good config)" systemctl reload "$UNIT"
wait_for 10 status_has '^F6A;'
check "the good reload took (STATUS: $(prop StatusText))" grep -q '^F6A;' <<<"$(prop StatusText)"
check "the reload kept the process" test "$(prop MainPID)" = "$pid"

# 5. Reload with a bad config: refused, the old settings stay, STATUS= names FILE:LINE:COL.
config HD1 $'rate=fast\n'
check "systemctl reload (bad config)" systemctl reload "$UNIT"
wait_for 10 status_has 'reload failed'
status=$(prop StatusText)
echo "   STATUS: $status"
check "the bad reload is refused, STATUS= names the file, line and column" \
  grep -Eq "reload failed: $CONF:[0-9]+:[0-9]+: error" <<<"$status"
check "the old settings stay (robot F6A)" grep -q '^F6A;' <<<"$status"
check "the bad reload kept the process" test "$(prop MainPID)/$(prop ActiveState)" = "$pid/active"
config F6A  # for the restarts below (read at start)

# 6. A stopped frame loop: the watchdog kills the process, and systemd starts a new one.
need "still running (pid $pid) before its SIGSTOP" test "$(prop MainPID)" = "$pid" -a "$pid" -gt 0
kill -STOP "$pid"
restarted() { [[ $(prop NRestarts) == 1 && $(prop ActiveState) == active ]]; }
wait_for 30 restarted
newpid=$(prop MainPID)
check "a SIGSTOPped bridge is restarted (NRestarts $(prop NRestarts), pid $pid -> $newpid)" \
  test "$(prop NRestarts)" = 1 -a "$newpid" != "$pid" -a "$(prop ActiveState)" = active
check "by the watchdog" journalctl -u "$UNIT" --no-pager -q --grep 'Watchdog timeout'
check "the stopped process is gone" bash -c "! kill -0 $pid 2>/dev/null"

# 7. Stop: neutral frames after driving ones, exit 0, within 2 s (systemd's own timestamps).
wait_for 30 driving_now || fail "the restarted bridge never drove"
check "systemctl stop" systemctl stop "$UNIT"
exit_us=$(prop ActiveExitTimestampMonotonic) inactive_us=$(prop InactiveEnterTimestampMonotonic)
echo "   stopped $(((inactive_us - exit_us) / 1000)) ms after the stop began"
check "the stop ended within 2 s" test "$exit_us" -gt 0 -a "$inactive_us" -ge "$exit_us" -a $((inactive_us - exit_us)) -le 2000000
check "the bridge exited 0 (Result $(prop Result), status $(prop ExecMainStatus))" \
  test "$(prop Result)/$(prop ExecMainCode)/$(prop ExecMainStatus)" = success/1/0
# The reader has drained the port once the capture stops growing.
size=-1
for _ in $(seq 50); do [[ $(stat -c %s "$CAPTURE") == "$size" ]] && break; size=$(stat -c %s "$CAPTURE"); sleep 0.2; done
frames >"$T/frames.json"
check "the stop sent neutral frames after driving ones ($(wc -l <"$T/frames.json") frames captured)" \
  python3 "$CHECK_FRAMES" --bin andros-bridge --min 50 --neutral-tail 3 --driving-before-tail <"$T/frames.json"

# 8. The session in the StateDirectory.
session=$(ls -t /var/lib/private/andros-bridge/*.andros-session 2>/dev/null | head -1)
check "the StateDirectory holds the sessions (/var/lib/andros-bridge -> private)" test -n "$session" -a -d /var/lib/andros-bridge
andros-bridge verify "$session" >"$T/verify" 2>&1
check "the stopped run's session verifies: $(head -1 "$T/verify"), $(sed -n 2p "$T/verify" | cut -d: -f1)" \
  grep -q '^closed' "$T/verify"

# 9. The exposure systemd-analyze gives the running system's unit.
exposure=$(systemd-analyze security --no-pager "$UNIT" | sed -n 's/.*Overall exposure level for.*: \([0-9.]*\).*/\1/p')
check "systemd-analyze security: exposure ${exposure:-?} <= 2.0" awk -v e="${exposure:-99}" 'BEGIN { exit !(e <= 2.0) }'

# 10. Enable, upgrade (the same package again: a restart of the enabled service), remove.
check "systemctl enable --now" systemctl enable --now "$UNIT"
check "enabled" test "$(systemctl is-enabled "$UNIT")" = enabled
pid=$(prop MainPID)
dpkg -i --force-confold "$DEB" >"$T/dpkg.log" 2>&1 || cat "$T/dpkg.log"
check "dpkg -i again (upgrade)" installed
# The postinst's restart has returned; active again with another process (a
# bound: the restart's own start is over, but a port the pty's reader had not
# yet released would cost one RestartSec=).
running_anew() { [[ $(prop ActiveState) == active && $(prop MainPID) != "$pid" ]]; }
wait_for 30 running_anew
check "the upgrade restarted the enabled service (pid $pid -> $(prop MainPID))" \
  test "$(prop ActiveState)" = active -a "$(prop MainPID)" != "$pid"
check "still enabled after the upgrade" test "$(systemctl is-enabled "$UNIT")" = enabled
check "the upgrade kept the edited config" grep -q '^robot=F6A' "$CONF"
dpkg -r andros-bridge >"$T/dpkg.log" 2>&1 || cat "$T/dpkg.log"
check "dpkg -r (remove)" bash -c "! dpkg-query -W -f='\${Status}' andros-bridge | grep -q 'ok installed'"
check "removed: the service stopped and its unit gone" test "$(prop LoadState)/$(prop ActiveState)" = not-found/inactive
finish
