# A serial port that stops taking frames (a pty nobody reads, its buffer
# full): the shutdown's neutral frames cannot be handed over, and `run` says
# so and exits 1 instead of reporting a normal stop.
source "$(dirname "$0")/lib.sh"
LIVE=$DATA/live
export XDG_CONFIG_HOME=$TMP/xdg

python3 - "$BIN" "$LIVE/long_drive.events" >"$TMP/out" 2>"$TMP/err" <<'PY'
import glob, os, pty, re, signal, subprocess, sys, time, tty
master, slave = pty.openpty()
tty.setraw(master)
# 300 frames a second fill the pty's ~20 kB in about 2 s; nobody reads it. The
# SIGTERM goes once the run has recorded a frame the full port refused (busy):
# on a loaded machine, skipped ticks fill it later.
p = subprocess.Popen([sys.argv[1], "run", "--port", os.ttyname(slave), "--baud", "115200", "--rate", "300",
                      "--input", sys.argv[2]], stderr=subprocess.PIPE)
sessions = os.path.join(os.environ["XDG_STATE_HOME"], "andros-bridge", "*.andros-session")
busy = re.compile(r"^[0-9]+ frame [0-9]+ [0-9]+ busy ", re.M)
deadline = time.monotonic() + 60  # a ceiling
while time.monotonic() < deadline and p.poll() is None:
    if any(busy.search(open(f).read()) for f in glob.glob(sessions)):
        break
    time.sleep(0.1)
p.send_signal(signal.SIGTERM)
_, err = p.communicate(timeout=10)
sys.stderr.write(err.decode())
sys.exit(p.returncode)
PY
code=$?
[[ $code -eq 1 ]] || fail "SIGTERM with a full pty exited $code, expected 1: $(cat "$TMP/err")"
grep -q "^error: only 0 of 3 neutral frames could be handed to the link (/dev/pts/[0-9]* 115200 8N1): the vehicle may still be acting on the last command it got" "$TMP/err" ||
  fail "no error line: $(cat "$TMP/err")"
(($(grep -c "error" "$TMP/err") == 1)) || fail "not one error line: $(cat "$TMP/err")"
finish
