# A second bridge on a port another program holds: refused at start, exit 2,
# one line naming the holder (andros-bridge and its PID, or the program that
# locked the port), and not one of its frames reaches the port, not even once
# the first bridge has gone (it would have taken the port over, enabled).
source "$(dirname "$0")/lib.sh"
export XDG_CONFIG_HOME=$TMP/xdg  # no user config file may change these runs

# Bridge 1 (code 01) streams to a pty; bridge 2 (code 3C, so that its frames
# would show) is started on the same port from a flag, then from a config
# file; then bridge 1 stops and this script locks the port as another program
# would. Bridge 2's exit code and stderr go to files, the pty's bytes to cap.
python3 - "$BIN" "$DATA/live/long_drive.events" "$TMP" <<'PY'
import os, pty, signal, subprocess, sys, time, tty, fcntl

binary, events, tmp = sys.argv[1:4]
master, slave = pty.openpty()
tty.setraw(master)
port = os.ttyname(slave)
os.set_blocking(master, False)
capture = bytearray()


def pump(until, limit):
    """Reads the pty until until() holds or limit seconds pass."""
    end = time.monotonic() + limit
    while not until() and time.monotonic() < end:
        time.sleep(0.02)
        try:
            capture.extend(os.read(master, 65536))
        except BlockingIOError:
            pass


def save(name, text):
    with open(os.path.join(tmp, name), "w") as f:
        f.write(str(text))


with open(os.path.join(tmp, "b2.conf"), "w") as f:
    f.write(f"code=3C\nserialport={port}\n")
bridge1 = subprocess.Popen([binary, "run", "--port", port, "--code", "01", "--input", events],
                           stderr=open(os.path.join(tmp, "b1.err"), "w"))
save("port", port)
save("b1.pid", bridge1.pid)
save("self.pid", os.getpid())
save("self.comm", open("/proc/self/comm").read().strip())
pump(lambda: capture.count(b"\xf1\xf1") >= 5, 10)  # bridge 1 holds the port

cases = [("flag", ["--port", port, "--code", "3C"]), ("config", ["--config", os.path.join(tmp, "b2.conf")])]
for name, args in cases:
    bridge2 = subprocess.Popen([binary, "run", *args, "--input", events], stderr=subprocess.PIPE)
    pump(lambda: bridge2.poll() is not None, 5)
    if bridge2.poll() is None:
        # Still waiting for the port: show what it does once bridge 1 lets go.
        bridge1.send_signal(signal.SIGTERM)
        bridge1.wait(10)
        pump(lambda: False, 1.5)
        bridge2.send_signal(signal.SIGTERM)
    _, err = bridge2.communicate(timeout=10)
    save(f"b2.{name}.err", err.decode(errors="replace"))
    save(f"b2.{name}.code", bridge2.returncode if bridge1.poll() is None else "running until bridge 1 stopped")
    if bridge1.poll() is not None:
        break

if bridge1.poll() is None:
    bridge1.send_signal(signal.SIGTERM)
    pump(lambda: bridge1.poll() is not None, 10)
    pump(lambda: False, 0.3)  # the last neutral frames
save("b1.code", bridge1.wait(10))

# Another program holds the port's lock (as picocom or flock(1) would).
held = os.open(port, os.O_RDWR | os.O_NOCTTY)
fcntl.flock(held, fcntl.LOCK_EX | fcntl.LOCK_NB)
bridge2 = subprocess.Popen([binary, "run", "--port", port, "--code", "3C", "--input", events], stderr=subprocess.PIPE)
pump(lambda: bridge2.poll() is not None, 5)
if bridge2.poll() is None:
    os.close(held)
    pump(lambda: False, 1.5)
    bridge2.send_signal(signal.SIGTERM)
_, err = bridge2.communicate(timeout=10)
save("b2.other.err", err.decode(errors="replace"))
save("b2.other.code", bridge2.returncode)
pump(lambda: False, 0.2)
with open(os.path.join(tmp, "cap"), "wb") as f:
    f.write(capture)
PY
(($? == 0)) || fail "the harness failed"

port=$(cat "$TMP/port")
b1=$(cat "$TMP/b1.pid")
# expect_refused CASE PREFIX HOLDER REASON: bridge 2's exit and its one stderr line.
expect_refused() {
  local got; got=$(cat "$TMP/b2.$1.code" 2>/dev/null)
  [[ $got == 2 ]] || fail "bridge 2 ($1) exited '$got', expected 2: $(cat "$TMP/b2.$1.err" 2>/dev/null)"
  # With --config, the run's first line names the file: then the error is the only other line.
  grep -v "^info: config: $TMP/b2.conf\$" "$TMP/b2.$1.err" >"$TMP/err" 2>/dev/null
  expect_one_line_stderr
  expect_stderr_matches "^$2: error: serial port '$port' is in use by $3: $4\$"
}
expect_refused flag "--port" "andros-bridge \(PID $b1\)" "a second bridge is refused"
expect_refused config "$TMP/b2.conf:2:12" "andros-bridge \(PID $b1\)" "a second bridge is refused"
expect_refused other "--port" "$(cat "$TMP/self.comm") \(PID $(cat "$TMP/self.pid")\)" "the bridge will not share it"

# Bridge 1 was not disturbed, and every frame on the port is its own.
[[ $(cat "$TMP/b1.code") == 0 ]] || fail "bridge 1 exited $(cat "$TMP/b1.code"): $(cat "$TMP/b1.err")"
grep -q "stopped (SIGTERM)" "$TMP/b1.err" || fail "bridge 1 did not run to its stop: $(cat "$TMP/b1.err")"
"$BIN" frame decode "$TMP/cap" 2>/dev/null | python3 -c '
import json, sys
codes = [json.loads(l)["signals"]["code"] for l in sys.stdin if l.strip()]
others = sum(c != 1 for c in codes)
print(f"{len(codes)} frames, {others} not from bridge 1 (code 01)")
sys.exit(0 if codes and others == 0 else 1)' >"$TMP/codes" || fail "frames on the port: $(cat "$TMP/codes")"
finish
