# `monitor`: the vehicle's view of a capture file and of a stream.
source "$(dirname "$0")/lib.sh"
export XDG_CONFIG_HOME=$TMP/xdg

# A capture made by the bridge itself (replay-free: run to a pty via the harness).
# A real-time run: on a loaded machine the clock may skip a tick, so the capture
# holds the frames the run says it sent (24 when none is skipped), each valid.
python3 "$(dirname "$0")/pty_harness.py" "$TMP/cap" -- "$BIN" run --port {PTY} --code 3C \
  --input "$DATA/live/drive.events" 2>"$TMP/cap.err" || fail "capture run failed: $(cat "$TMP/cap.err")"
sent=$(sed -n 's/.*(end of the input): \([0-9]*\) frames sent.*/\1/p' "$TMP/cap.err")
[[ $sent -ge 20 && $sent -le 24 ]] || fail "capture run: frames sent '$sent': $(cat "$TMP/cap.err")"
[[ $(stat -c %s "$TMP/cap") -eq $((sent * 36)) ]] || fail "capture: $(stat -c %s "$TMP/cap") bytes for $sent frames"

expect_exit 0 "$BIN" monitor "$TMP/cap"
grep -q "^frames      $sent, valid $sent, bad checksum 0, invalid 0, bytes skipped 0 of $((sent * 36))" "$TMP/out" ||
  fail "capture summary: $(cat "$TMP/out")"
grep -q "^last frame  valid" "$TMP/out" || fail "last frame: $(cat "$TMP/out")"
grep -q "drive      \[          |          \] 128" "$TMP/out" || fail "gauge: $(cat "$TMP/out")"
# --code: frames with another byte 11 are invalid.
expect_exit 0 "$BIN" monitor --code 01 "$TMP/cap"
grep -q "valid 0, bad checksum 0, invalid $sent" "$TMP/out" || fail "--code: $(cat "$TMP/out")"
grep -q "INVALID: byte 11 code 0x3C, expected 0x01" "$TMP/out" || fail "--code errors: $(cat "$TMP/out")"
# The mixed capture: errors counted.
expect_exit 0 "$BIN" monitor "$DATA/mixed_capture.bin"
grep -q "bad checksum [1-9]" "$TMP/out" || fail "mixed capture: $(cat "$TMP/out")"

# A stream on standard input, to its end: live rate line, log lines off a terminal.
run_cmd "$BIN" monitor - <"$TMP/cap"
[[ $code -eq 0 ]] || fail "monitor - exited $code"
grep -q "^rate " "$TMP/out" || fail "stream view: $(cat "$TMP/out")"
grep -q "frames      $sent, valid $sent" "$TMP/out" || fail "stream summary: $(cat "$TMP/out")"
grep -q "frames arriving" "$TMP/err" || fail "stream log: $(cat "$TMP/err")"

# A serial port (a pty): frames at 25 Hz, then Ctrl-C (SIGINT) -> summary, exit 0;
# a port that hangs up (unplugged) -> exit 1.
python3 - "$BIN" "$TMP/cap" "$TMP/port.out" <<'PY' || fail "monitor on a pty (above)"
import os, pty, signal, subprocess, sys, time, tty
bin_, cap, out = sys.argv[1:]
frames = open(cap, "rb").read()
def start():
    m, s = pty.openpty(); tty.setraw(m); tty.setraw(s)  # raw before the monitor opens it
    p = subprocess.Popen([bin_, "monitor", os.ttyname(s)], stdout=open(out, "w"), stderr=subprocess.STDOUT)
    # Once it listens (the stop signals blocked, after it opened and flushed the port): a frame
    # written before would be flushed away, or a signal meet its default action.
    for _ in range(600):  # bounded: 30 s
        blocked = [l for l in open(f"/proc/{p.pid}/status") if l.startswith("SigBlk:")]
        if blocked and int(blocked[0].split()[1], 16) >> (signal.SIGINT - 1) & 1: break
        time.sleep(0.05)
    for i in range(0, len(frames), 36):
        os.write(m, frames[i:i + 36]); time.sleep(0.04)  # a switchbox's pace
    for _ in range(600):  # bounded wait (30 s): the monitor has seen the frames
        if "frames arriving" in open(out).read(): break
        time.sleep(0.05)
    return m, s, p
m, s, p = start()
p.send_signal(signal.SIGINT)
code = p.wait(timeout=10)
text = open(out).read()
n = len(frames) // 36
if not (code == 0 and f"frames      {n}, valid {n}," in text and "rate " in text):
    sys.exit(f"Ctrl-C: exit {code}, expected 0 and {n} valid frames: {text}")
m2, s2, p2 = start()
os.close(m2); os.close(s2)
code = p2.wait(timeout=10)
if code != 1:
    sys.exit(f"unplugged: exit {code}, expected 1: {open(out).read()}")
PY

expect_exit 2 "$BIN" monitor "$TMP/none"
expect_one_line_stderr
expect_stderr_matches "none: error: cannot open"
expect_exit 2 "$BIN" monitor --baud 1234 "$TMP/cap"
expect_exit 0 "$BIN" monitor --help
finish
