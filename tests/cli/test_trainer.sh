# `trainer` end to end (docs/trainer.md): a port other than the simulated
# vehicle is refused from a flag or a config line, in one line, exit 2, before
# anything is opened; a drive script moves the page's vehicle (GET /state);
# a port taken and a non-loopback address do not stop the driving.
source "$(dirname "$0")/lib.sh"
export XDG_CONFIG_HOME=$TMP/xdg  # no user config file may change these runs
DRIVE=$DATA/trainer/drive_course.events
free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }

# A serial port, a TCP link, from a flag: refused, one line.
for port in /dev/ttyS0 /dev/ttyUSB0 tcp:127.0.0.1:4001; do
  expect_exit 2 "$BIN" trainer --port "$port" --input "$DRIVE" --exit-at-end
  expect_one_line_stderr
  expect_stderr_matches "^--port: error: the trainer drives only its simulated vehicle: port '$port' refused"
done
# From a config file's line: the line is named (after the log's line that names the file).
sed "s|PORT|/dev/ttyS0|" "$DATA/live/legacy.conf" >"$TMP/legacy.conf"
expect_exit 2 "$BIN" trainer --config "$TMP/legacy.conf" --input "$DRIVE" --exit-at-end
[[ $(grep -c "error" "$TMP/err") -eq 1 ]] || fail "more than one error line: $(cat "$TMP/err")"
tail -1 "$TMP/err" | grep -q "legacy.conf:5:.*the trainer drives only its simulated vehicle: port '/dev/ttyS0' refused" ||
  fail "config line not refused: $(cat "$TMP/err")"
# `--port sim` is the trainer's own link: taken. Its help says so, not `run`'s "a serial device".
expect_exit 0 "$BIN" trainer --help
tr -s ' \n' ' ' <"$TMP/out" >"$TMP/help"
grep -q -- "--port sim *where frames go: only sim, the built-in simulated vehicle (the default); a serial device or a TCP link, here or in the config file, is refused" "$TMP/help" ||
  fail "trainer --help's --port: $(grep -A3 -- --port "$TMP/out")"
grep -q "refused at start while another program holds it" "$TMP/help" && fail "trainer --help offers run's serial device"
# A bad --listen: one line, exit 2.
expect_exit 2 "$BIN" trainer --listen 127.0.0.1 --input "$DRIVE" --exit-at-end
expect_one_line_stderr
expect_stderr_matches "^--listen: error: "

# The drive moves the page's vehicle: /state read while it runs.
PORT=$(free_port)
"$BIN" trainer --port sim --listen "127.0.0.1:$PORT" --input "$DRIVE" --exit-at-end >"$TMP/out" 2>"$TMP/err" &
pid=$!
python3 - "$PORT" >"$TMP/poll" 2>&1 <<'PY' || fail "the page's state did not follow the drive: $(cat "$TMP/poll")"
import json, sys, time, urllib.request
port = int(sys.argv[1])
deadline, best = time.monotonic() + 30, None
while time.monotonic() < deadline:
    try:
        with urllib.request.urlopen(f"http://127.0.0.1:{port}/state", timeout=2) as r:
            s = json.loads(r.read())
    except OSError:
        time.sleep(0.1)
        continue
    if "pose" in s:
        best = s
        if s["pose"]["x"] > 2.0 and s["state_name"] == "enabled" and s["state"] == "ENABLED" and len(s["trail"]) > 10:
            print("moving:", s["pose"], s["tick"])
            sys.exit(0)
    time.sleep(0.1)
print("last state:", best)
sys.exit(1)
PY
wait $pid
code=$?
[[ $code -eq 0 ]] || fail "trainer exited $code: $(cat "$TMP/err")"
grep -q "trainer: the simulated vehicle's page is at http://127.0.0.1:$PORT/" "$TMP/err" || fail "no address: $(cat "$TMP/err")"
grep -q "stopped (end of the input)" "$TMP/err" || fail "no closing line: $(cat "$TMP/err")"

# The port taken by another program: said, and the drive goes on to its end.
python3 -c 'import socket, time
s = socket.socket(); s.bind(("127.0.0.1", 0)); s.listen()
print(s.getsockname()[1], flush=True); time.sleep(60)' >"$TMP/holder" &
holder=$!
for _ in $(seq 50); do [[ -s $TMP/holder ]] && break; sleep 0.1; done
TAKEN=$(cat "$TMP/holder")
expect_exit 0 "$BIN" trainer --listen "127.0.0.1:$TAKEN" --input "$DATA/live/drive.events" --exit-at-end
kill "$holder"
expect_stderr_matches "trainer: cannot listen on 127.0.0.1:$TAKEN.*no page, driving goes on"
expect_stderr_matches "stopped \(end of the input\): [0-9]+ frames sent"

# Another address than 127.0.0.1: warned about.
PORT=$(free_port)
expect_exit 0 "$BIN" trainer --listen "0.0.0.0:$PORT" --input "$DATA/live/drive.events" --exit-at-end
expect_stderr_matches "listens on 0.0.0.0:$PORT, not only this machine"
finish
