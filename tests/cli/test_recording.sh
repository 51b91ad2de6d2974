# The flight recorder (docs/recording.md) end to end: on by default, verify,
# replay of a session (a link loss, a reload and a Ctrl-Z inside it),
# tampering found, sessions, the settings, rotation, a folder it cannot use.
source "$(dirname "$0")/lib.sh"
HERE=$(dirname "$0")
LIVE=$DATA/live
export XDG_CONFIG_HOME=$TMP/xdg  # no user config file may change these runs
STATE=$XDG_STATE_HOME/andros-bridge
harness() { python3 "$HERE/pty_harness.py" "$@"; }
sessions() { ls "$STATE"/*.andros-session 2>/dev/null; }
newest() { sessions | tail -1; }
# frames_in CAPTURE: the frames the port got.
frames_in() { "$BIN" frame decode "$1" 2>/dev/null | wc -l; }
# replays_exactly SESSION CAPTURE WHAT: replay says every frame the port got is reproduced.
replays_exactly() {
  expect_exit 0 "$BIN" replay "$1"
  local n; n=$(frames_in "$2")
  grep -qE "^$n frames identical; [0-9]+ records .* made again the same$" "$TMP/out" ||
    fail "$3: replay said '$(cat "$TMP/out")', expected $n frames and every record identical"
  ((n > 20)) || fail "$3: only $n frames captured"
}

# On by default: a run on a pty writes one session in $XDG_STATE_HOME/andros-bridge.
run_cmd harness "$TMP/cap" -- "$BIN" run --robot hd1 --port {PTY} --input "$LIVE/drive.events"
[[ $code -eq 0 ]] || fail "run exited $code: $(cat "$TMP/err")"
[[ $(sessions | wc -l) -eq 1 ]] || fail "expected one session in $STATE: $(ls -la "$STATE" 2>&1)"
session=$(newest)
[[ $(basename "$session") =~ ^[0-9]{8}-[0-9]{6}-[0-9]+\.andros-session$ ]] || fail "session name: $session"
[[ $(stat -c %a "$session") == 640 ]] || fail "session mode $(stat -c %a "$session"), expected 640"
grep -q "recording to $session" "$TMP/err" || fail "the log does not say where the session goes"
grep -Eq "recorded [0-9]+ records to $session \(last hash [0-9a-f]{64}\)" "$TMP/err" || fail "no closing line"
hash=$(grep -Eo "last hash [0-9a-f]{64}" "$TMP/err" | cut -d' ' -f3)
head -1 "$session" | grep -q "^0 andros-session 4 " || fail "first line: $(head -1 "$session")"

expect_exit 0 "$BIN" verify "$session"
head -1 "$TMP/out" | grep -Eqx "intact \([0-9]+ records\)" || fail "verify: $(cat "$TMP/out")"
grep -qx "last hash: $hash" "$TMP/out" || fail "verify's last hash is not the log's: $(cat "$TMP/out")"
grep -q "^closed" "$TMP/out" || fail "verify: not closed"
replays_exactly "$session" "$TMP/cap" "plain drive"

expect_exit 0 "$BIN" sessions
grep -q "^sessions in $STATE:" "$TMP/out" || fail "sessions: $(cat "$TMP/out")"
grep -Eq "HD1 +$(frames_in "$TMP/cap") +no +0 +0 +0 +0 +intact +$(basename "$session")" "$TMP/out" ||
  fail "sessions: $(cat "$TMP/out")"

# Tampering: an altered byte, a removed record, a swapped pair; verify and replay refuse.
tamper() { cp "$session" "$TMP/t.andros-session"; python3 -c "$1" "$TMP/t.andros-session"; }
tamper 'import sys; p=sys.argv[1]; l=open(p).read().split("\n"); l[12]=l[12].replace(" ", "  ", 1); open(p,"w").write("\n".join(l))'
expect_exit 1 "$BIN" verify "$TMP/t.andros-session"
expect_stdout "NOT INTACT: record 12 (line 13) altered: its content or hash no longer matches the chain"
expect_exit 1 "$BIN" replay "$TMP/t.andros-session"
grep -q "^NOT INTACT: record 12" "$TMP/out" || fail "replay of an altered session: $(cat "$TMP/out")"
tamper 'import sys; p=sys.argv[1]; l=open(p).read().split("\n"); del l[9]; open(p,"w").write("\n".join(l))'
expect_exit 1 "$BIN" verify "$TMP/t.andros-session"
expect_stdout "NOT INTACT: record 9 removed (before line 10)"
tamper 'import sys; p=sys.argv[1]; l=open(p).read().split("\n"); l[7],l[8]=l[8],l[7]; open(p,"w").write("\n".join(l))'
expect_exit 1 "$BIN" verify "$TMP/t.andros-session"
expect_stdout "NOT INTACT: record 7 reordered: found at line 9, after record 8 (line 8)"

# A link loss (the port unplugged and plugged again) and a reload inside the session.
{ grep -v "^[0-9]* *end" "$LIVE/long_drive.events" | sed '/^60000/d'; echo "3000 reload"; echo "3600 button leftshoulder 0";
  echo "3700 button leftshoulder 1"; echo "3800 axis lefty 0"; echo "4000 axis lefty -20000"; echo "6000 end"; } >"$TMP/faults.events"
run_cmd harness "$TMP/cap2" --replug-after 30 -- "$BIN" run --robot hd1 --port {PTY} --input "$TMP/faults.events"
[[ $code -eq 0 ]] || fail "replug run exited $code: $(cat "$TMP/err")"
grep -q "reloaded" "$TMP/err" || fail "no reload in the run: $(cat "$TMP/err")"
s2=$(newest)
grep -q " link [0-9]* connecting" "$s2" || fail "no link loss recorded"
grep -q " reload [0-9]* ok " "$s2" || fail "no reload recorded"
cat "$TMP/cap2" "$TMP/cap2.2" >"$TMP/cap2.all"
replays_exactly "$s2" "$TMP/cap2.all" "link loss and reload"

# A Ctrl-Z (neutral frames, stopped) and SIGCONT inside the session.
python3 - "$BIN" "$HERE" "$LIVE/long_drive.events" "$TMP/cap3" <<'PY' || fail "Ctrl-Z run failed"
import signal, subprocess, sys, time
sys.path.insert(0, sys.argv[2])
sys.dont_write_bytecode = True
from fault_lib import Port, driving, start, wait_exit, wait_stopped
bin_, script, capture = sys.argv[1], sys.argv[3], sys.argv[4]
port = Port()
proc = start([bin_, "run", "--port", port.path, "--input", script],
             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL)
ok = port.wait(lambda f: driving(f) >= 5, 10)
proc.send_signal(signal.SIGTSTP)
ok = ok and wait_stopped(proc)
time.sleep(0.4)
proc.send_signal(signal.SIGCONT)
n = len(port.received())
ok = ok and port.wait(lambda f: len(f) >= n + 10, 5)
proc.send_signal(signal.SIGTERM)
ok = wait_exit(proc, 10) == 0 and ok
port.close(capture)
sys.exit(0 if ok else 1)
PY
s3=$(newest)
grep -q " request [0-9]* suspend " "$s3" || fail "no suspend recorded"
grep -q " pause [0-9]* " "$s3" || fail "no pause recorded"
grep -q " request [0-9]* stop " "$s3" || fail "no stop recorded"
replays_exactly "$s3" "$TMP/cap3" "Ctrl-Z"

# The plot of a session.
expect_exit 0 "$BIN" plot "$session" --output "$TMP/s.svg"
python3 -c "import sys, xml.etree.ElementTree as ET; t=''.join(ET.parse(sys.argv[1]).getroot().itertext()); sys.exit(0 if 'HD1 drive' in t and 'safety' in t else 1)" "$TMP/s.svg" ||
  fail "the session's plot lacks its title or signals"

# --no-record, record=disabled: nothing written; --record-dir: there.
before=$(sessions | wc -l)
run_cmd harness "$TMP/cap" -- "$BIN" run --no-record --port {PTY} --input "$LIVE/drive.events"
[[ $code -eq 0 && $(sessions | wc -l) -eq $before ]] || fail "--no-record wrote a session (exit $code)"
mkdir -p "$XDG_CONFIG_HOME/andros-bridge"
echo "record=disabled" >"$XDG_CONFIG_HOME/andros-bridge/andros-bridge.conf"
run_cmd harness "$TMP/cap" -- "$BIN" run --port {PTY} --input "$LIVE/drive.events"
[[ $code -eq 0 && $(sessions | wc -l) -eq $before ]] || fail "record=disabled wrote a session (exit $code)"
rm "$XDG_CONFIG_HOME/andros-bridge/andros-bridge.conf"
run_cmd harness "$TMP/cap" -- "$BIN" run --record-dir "$TMP/elsewhere" --port {PTY} --input "$LIVE/drive.events"
[[ $(ls "$TMP/elsewhere"/*.andros-session | wc -l) -eq 1 ]] || fail "--record-dir: $(ls "$TMP/elsewhere" 2>&1)"
# The service's folder (systemd's StateDirectory=).
STATE_DIRECTORY=$TMP/service run_cmd harness "$TMP/cap" -- "$BIN" run --port {PTY} --input "$LIVE/drive.events"
[[ $(ls "$TMP/service"/*.andros-session | wc -l) -eq 1 ]] || fail "STATE_DIRECTORY: $(ls "$TMP/service" 2>&1)"

# Rotation: over the size cap, the oldest go first; past the age, they go whatever the size.
mkdir -p "$TMP/rot"
# Sessions: their first line says so (test_session_evidence.sh tries files that are not).
old_session() { { printf '0 andros-session 2 %064d\n' 0; head -c "$2" /dev/zero; } >"$TMP/rot/$1.andros-session"; }
old_session 20200101-000000-1 700000
old_session 20200102-000000-1 700000
old_session 20200103-000000-1 10
touch -d '40 days ago' "$TMP/rot/20200103-000000-1.andros-session"
run_cmd harness "$TMP/cap" -- "$BIN" run --record-dir "$TMP/rot" --record-max-mb 1 --port {PTY} --input "$LIVE/drive.events"
[[ ! -e $TMP/rot/20200101-000000-1.andros-session ]] || fail "the oldest session over the cap was kept"
[[ -e $TMP/rot/20200102-000000-1.andros-session ]] || fail "a session within the cap was removed"
[[ ! -e $TMP/rot/20200103-000000-1.andros-session ]] || fail "a session past its age was kept"
grep -q "removed $TMP/rot/20200101-000000-1.andros-session (rotation)" "$TMP/err" || fail "rotation not logged"
[[ $(ls "$TMP/rot" | wc -l) -eq 2 ]] || fail "rotation: $(ls "$TMP/rot")"

# A folder it cannot use: the run goes on, unrecorded, and says so.
touch "$TMP/file"
run_cmd harness "$TMP/cap" -- "$BIN" run --record-dir "$TMP/file/sub" --port {PTY} --input "$LIVE/drive.events"
[[ $code -eq 0 ]] || fail "an unusable record folder ended the run ($code)"
grep -q "this run is not recorded" "$TMP/err" || fail "no warning for an unusable record folder"
(($(frames_in "$TMP/cap") > 20)) || fail "no frames with an unusable record folder"

# Errors: exit 2, one line.
expect_exit 2 "$BIN" verify "$TMP/none.andros-session"
expect_one_line_stderr
expect_exit 2 "$BIN" replay "$session" --robot hd1
expect_stderr_matches "^--robot: error: not for a session"
expect_exit 2 "$BIN" run --record-max-mb 0
expect_stderr_matches "record_max_mb"
expect_exit 0 "$BIN" sessions --record-dir "$TMP/empty"
expect_stdout "no sessions in $TMP/empty"

finish
