# `run` end to end on pseudo-terminals, a local TCP listener and the simulator.
source "$(dirname "$0")/lib.sh"
HERE=$(dirname "$0")
LIVE=$DATA/live
export XDG_CONFIG_HOME=$TMP/xdg  # no user config file may change these runs
harness() { python3 "$HERE/pty_harness.py" "$@"; }
# check CAPTURE ARGS...: the capture's frames pass check_frames.py ARGS.
check() {
  local cap=$1; shift
  "$BIN" frame decode "$cap" 2>/dev/null | python3 "$HERE/check_frames.py" --bin "$BIN" "$@" >"$TMP/check" ||
    fail "$cap: $(cat "$TMP/check")"
}

# Acceptance: run --robot hd1 --port PTY --input SCRIPT.
run_cmd harness "$TMP/cap" -- "$BIN" run --robot hd1 --port {PTY} --input "$LIVE/drive.events"
[[ $code -eq 0 ]] || fail "run exited $code: $(cat "$TMP/err")"
check "$TMP/cap" --min 20 --enabled --driving --neutral-tail 3 --code 01
grep -q "stopped (end of the input)" "$TMP/err" || fail "no closing line: $(cat "$TMP/err")"
grep -q "link .*: up" "$TMP/err" || fail "link state not logged"
[[ $(grep -c "link .*: up" "$TMP/err") -eq 1 ]] || fail "link state logged more than once"

# Started with stdin, stdout and stderr closed (`<&- >&- 2>&-`): the port must
# not take descriptor 0, 1 or 2, or log lines (and the status view) would go
# out on the vehicle's link between the frames, depending on a race.
python3 - "$BIN" "$LIVE/long_drive.events" <<'PY' || fail "a standard descriptor became the port"
import os, pty, subprocess, sys, time
master, slave = pty.openpty()
port = os.ttyname(slave)
p = subprocess.Popen(["sh", "-c", 'exec "$0" "$@" <&- >&- 2>&-', sys.argv[1], "run", "--port", port,
                      "--input", sys.argv[2]])
os.set_blocking(master, False)
data, deadline = b"", time.monotonic() + 10
while data.count(b"\xf1\xf1") < 10 and time.monotonic() < deadline:  # frames flow: the port is open
    time.sleep(0.05)
    try:
        data += os.read(master, 65536)
    except BlockingIOError:
        pass
fds = {fd: os.readlink(f"/proc/{p.pid}/fd/{fd}") for fd in (0, 1, 2) if os.path.exists(f"/proc/{p.pid}/fd/{fd}")}
p.terminate()
p.wait(10)
print(fds)
sys.exit(0 if data.count(b"\xf1\xf1") >= 10 and all(t == "/dev/null" for t in fds.values()) and len(fds) == 3 else 1)
PY

# The legacy config file drives a run: serialport = the pty, code = 3C -> byte 11.
sed "s|serialport=PORT|serialport=$TMP/port|" "$LIVE/legacy.conf" >"$TMP/legacy.conf"
run_cmd harness "$TMP/cap" --link "$TMP/port" -- "$BIN" run --config "$TMP/legacy.conf" --input "$LIVE/drive.events"
[[ $code -eq 0 ]] || fail "legacy config run exited $code: $(cat "$TMP/err")"
check "$TMP/cap" --min 20 --enabled --neutral-tail 3 --code 3C
# ...found at the default place too, and flags override it.
mkdir -p "$XDG_CONFIG_HOME/andros-bridge"
cp "$TMP/legacy.conf" "$XDG_CONFIG_HOME/andros-bridge/andros-bridge.conf"
run_cmd harness "$TMP/cap" --link "$TMP/port" -- "$BIN" run --code 5A --input "$LIVE/drive.events"
[[ $code -eq 0 ]] || fail "default config run exited $code: $(cat "$TMP/err")"
check "$TMP/cap" --min 20 --code 5A
grep -q "config: $XDG_CONFIG_HOME/andros-bridge/andros-bridge.conf" "$TMP/err" || fail "default config not named"
rm "$XDG_CONFIG_HOME/andros-bridge/andros-bridge.conf"

# Bad config lines: exit 2, one line naming FILE:LINE.
while IFS='|' read -r line want; do
  printf '# a comment\nserialport=sim\n%s\n' "$line" >"$TMP/bad.conf"
  expect_exit 2 "$BIN" run --config "$TMP/bad.conf" --input "$LIVE/drive.events"
  expect_one_line_stderr
  expect_stderr_matches "^$TMP/bad.conf:3(:[0-9]+)?: error: $want"
done <<'CASES'
baudrate=9601|baud 9601 is not one of
robot=R2D2|unknown robot 'R2D2'
code=GG|code 'GG' is not a byte in hex
colour=red|unknown key 'colour'
rate=fast|rate 'fast' is not a number of Hz
weapons=maybe|weapons 'maybe' must be enabled or disabled
no equals sign|expected key=value
serialport=sim|key 'serialport' given twice \(first at line 2\)
CASES
expect_exit 2 "$BIN" run --config "$TMP/missing.conf"
expect_stderr_matches "missing.conf: error: cannot read the config file"

# A rate whose frames cannot fit on the link is refused, from a flag or the file.
expect_exit 2 "$BIN" run --rate 30 --input "$LIVE/drive.events"
expect_one_line_stderr
expect_stderr_matches "^--rate: error: rate '30' does not fit the link: 360-bit frames at 9600 baud allow at most 26.666 Hz"
printf 'rate=60\nbaudrate=19200\n' >"$TMP/fast.conf"
expect_exit 2 "$BIN" run --config "$TMP/fast.conf" --input "$LIVE/drive.events"
expect_stderr_matches "fast.conf:1:6: error: rate '60' does not fit the link: 360-bit frames at 19200 baud"
expect_exit 2 "$BIN" run --config "$TMP/fast.conf" --baud 9600 --input "$LIVE/drive.events"
expect_stderr_matches "fast.conf:1:6: error: rate '60' does not fit the link: 360-bit frames at 9600 baud"
expect_exit 2 "$BIN" run --port "" --input "$LIVE/drive.events"
expect_stderr_matches "^--port: error: empty value"
for flag in "--baud 9601" "--code XYZ" "--robot R2D2" "--rate 0"; do
  expect_exit 2 "$BIN" run $flag --input "$LIVE/drive.events"
  expect_one_line_stderr
done
expect_exit 2 "$BIN" run --input "$TMP/no-such.events"
expect_stderr_matches "no-such.events: error: cannot read the event script"
printf '0 connect\n10 button nosuch 1\n' >"$TMP/bad.events"
expect_exit 2 "$BIN" run --input "$TMP/bad.events"
expect_stderr_matches "bad.events:2"

# A stick pushed through the deadman press is held back until centred, and the log says so.
printf '0 connect\n100 button leftshoulder 1\n100 axis lefty -32768\n500 axis lefty 0\n600 axis lefty -32768\n1000 end\n' >"$TMP/held.events"
expect_exit 0 "$BIN" run --input "$TMP/held.events"
expect_stderr_matches "info: enabled; at rest first: lefty"

# A port that does not exist: the deadman pressed and the stick pushed, but
# nothing reaches the vehicle, so the state is "no link", never "enabled".
printf '0 connect\n100 button leftshoulder 1\n300 axis lefty -32768\n600 end\n' >"$TMP/nolink.events"
expect_exit 1 "$BIN" run --port "$TMP/no-such-port" --input "$TMP/nolink.events"
expect_stderr_matches "info: no link: nothing reaches the vehicle"
grep -q "info: enabled" "$TMP/err" && fail "enabled said while nothing reached the vehicle: $(cat "$TMP/err")"

# SIGTERM mid-drive: neutral frames, drain, exit 0 (the harness bounds the wait).
run_cmd harness "$TMP/cap" --term-after 5 --driving --timeout 30 -- \
  "$BIN" run --port {PTY} --input "$LIVE/long_drive.events"
[[ $code -eq 0 ]] || fail "SIGTERM run exited $code: $(cat "$TMP/err")"
check "$TMP/cap" --min 8 --driving --neutral-tail 3
grep -q "stopped (SIGTERM)" "$TMP/err" || fail "no SIGTERM closing line: $(cat "$TMP/err")"

# Unplug/replug: the symlink moves from one pty to a new one; streaming resumes,
# and a link that comes back is a new link: with the deadman held throughout,
# nothing moves on it (a stop never ends by itself).
run_cmd harness "$TMP/cap" --replug-after 5 --term-after 10 --timeout 30 -- \
  "$BIN" run --port {PTY} --input "$LIVE/long_drive.events"
[[ $code -eq 0 ]] || fail "replug run exited $code: $(cat "$TMP/err")"
check "$TMP/cap" --min 5
check "$TMP/cap.2" --min 10 --all-neutral
grep -q "not enabled: link regained: press the deadman afresh" "$TMP/err" ||
  fail "the regained link does not say why nothing moves: $(cat "$TMP/err")"
# The first cause stays: the held deadman (its consequence) never replaces it.
! grep -q "deadman held since connect" "$TMP/err" || fail "a consequence replaced the first cause: $(cat "$TMP/err")"
[[ $(grep -c "lost" "$TMP/err") -eq 1 ]] || fail "the loss is not logged exactly once: $(cat "$TMP/err")"
[[ $(grep -c "link .*: up" "$TMP/err") -eq 2 ]] || fail "link up not logged twice: $(cat "$TMP/err")"

# A TCP serial server on 127.0.0.1.
python3 - "$TMP/tcp.port" "$TMP/tcp.cap" <<'PY' &
import socket, sys
s = socket.socket(); s.bind(("127.0.0.1", 0)); s.listen(1); s.settimeout(10)
open(sys.argv[1] + ".tmp", "w").write(str(s.getsockname()[1]))
import os; os.rename(sys.argv[1] + ".tmp", sys.argv[1])
c, _ = s.accept(); c.settimeout(10); data = b""
while True:
    d = c.recv(4096)
    if not d: break
    data += d
open(sys.argv[2], "wb").write(data)
PY
server=$!
for _ in $(seq 100); do [[ -f $TMP/tcp.port ]] && break; sleep 0.05; done
run_cmd "$BIN" run --port "tcp:127.0.0.1:$(cat "$TMP/tcp.port")" --input "$LIVE/drive.events"
[[ $code -eq 0 ]] || fail "tcp run exited $code: $(cat "$TMP/err")"
wait $server || fail "tcp listener failed"
check "$TMP/tcp.cap" --min 20 --enabled --neutral-tail 3
expect_exit 2 "$BIN" run --port tcp:127.0.0.1 --input "$LIVE/drive.events"
expect_stderr_matches "tcp:HOST:PORT"

# The default port: the built-in simulated vehicle decodes every frame.
expect_exit 0 "$BIN" run --input "$LIVE/drive.events"
expect_stderr_matches "sim vehicle decoded 24 frames: 24 valid, 0 bad checksum, 0 invalid"

# The bundled demo (scripts/run.sh with no arguments) enables, drives and ends at rest:
# checked on replay's virtual clock rather than in 12 s of real time.
"$BIN" replay "$HERE/../../demos/drive.events" --robot hd1 --format jsonl >"$TMP/demo.jsonl" 2>"$TMP/err" ||
  fail "demo script: $(cat "$TMP/err")"
python3 - "$TMP/demo.jsonl" <<'PY' || fail "the demo does not drive and stop"
import json, sys
fs = [json.loads(l)["signals"] for l in open(sys.argv[1])]
sys.exit(0 if any(f["safety"] and f["drive"] > 128 for f in fs) and fs[-1]["safety"] == 0 and fs[-1]["drive"] == 128 else 1)
PY

# On a terminal (120x40): the live status view, redrawn, with the log kept under it.
python3 - "$BIN" "$LIVE/drive.events" >"$TMP/tty.txt" <<'PY' || fail "status view: $(tail -c 600 "$TMP/tty.txt")"
import fcntl, os, pty, re, select, struct, subprocess, sys, termios
m, s = pty.openpty()
fcntl.ioctl(s, termios.TIOCSWINSZ, struct.pack("HHHH", 40, 120, 0, 0))  # room for every switch group
env = dict(os.environ, TERM="xterm")
p = subprocess.Popen([sys.argv[1], "run", "--input", sys.argv[2]], stdout=s, stderr=subprocess.DEVNULL, env=env)
os.close(s)
out = b""
while True:
    r, _, _ = select.select([m], [], [], 10)
    if not r: break
    try: data = os.read(m, 65536)
    except OSError: break
    if not data: break
    out += data
code = p.wait(timeout=10)
text = out.decode("utf-8", "replace")
screens = text.split("\x1b[H")
last = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", screens[-1])
print(last)
want = ["andros-bridge run", "controller  Test pad", "link        sim vehicle on", "vehicle     ",
        "as the vehicle decodes it:", "  drive    ", "  weapons  ", "drive      [", "light      [", "info: stopping: sending neutral frames"]
missing = [w for w in want if w not in last]
print("exit", code, "screens", len(screens), "missing", missing)
# Several redraws, everything shown, and the cursor given back at the end.
sys.exit(0 if code == 0 and len(screens) >= 3 and not missing and "\x1b[?25h" in text else 1)
PY

# The operator's pieces: help.
expect_exit 0 "$BIN" run --help
grep -q -- "--port" "$TMP/out" || fail "run --help"
finish
