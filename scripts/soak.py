#!/usr/bin/env python3
"""Soak test: the bridge at 25 Hz on a pseudo-terminal for a long time, fed a
random event script, with every frame checked. Not part of CI.

  scripts/soak.py [--seconds 3600] [--seed N] [--robot hd1] [--bin PATH] [--keep DIR]
                  [--close-log-after SECONDS]

It writes a random script (connects, disconnects, deadman presses and stuck
deadman, sticks, toggles, layers, selectors, taps), runs
`andros-bridge run --port PTY --input SCRIPT`, reads the pty's far end with a
timestamp per frame, samples the bridge's RSS, then decodes the capture with
`andros-bridge frame decode` and checks every frame:

- valid (checksum and validation table) with byte 11 = the code;
- no opposing pair both 1, no weapon bit (weapons are off);
- safety = 0 => neutral (motion, weapon and interlock bits 0, drive/pivot at centre);
- while the script says the bridge may not move (no controller, deadman not
  held, or not pressed afresh since the connect), with a frame of margin on
  either side, the frame is neutral: this reading of the safety rules (docs/mapping.md) is the
  script's own, not the engine's.

Opposing pairs and signal kinds come from `andros-bridge frame signals --json`.
With --close-log-after S, the bridge's stdout and stderr go into one pipe
whose reader keeps what it reads and closes its end S seconds in (an ssh
session carrying `| tee` that hangs up): the bridge must run on, and end on
its neutral frames.
Prints a report; exits 1 if any frame broke a rule, the run did not end with
at least 3 neutral frames, or the bridge did not exit 0.
"""
import argparse, bisect, json, os, pty, random, select, statistics, subprocess, sys, tempfile, threading, time, tty

PERIOD_MS = 40.0


def make_script(path, seconds, rng):
    """A random session. Returns the intervals [(start, end)] in which the
    bridge may move: connected, deadman held, pressed after the connect."""
    lines, t = ["0 connect Soak Pad"], 0
    connected, deadman, fresh = True, False, False
    may_move, since = [], None
    end = seconds * 1000

    def mark(now):
        nonlocal since
        ok = connected and deadman and fresh
        if ok and since is None:
            since = now
        elif not ok and since is not None:
            may_move.append((since, now))
            since = None

    while t < end - 2000:
        t += rng.choice([0, 5, 17, 40, 90, 250, 600, 1500])
        r = rng.random()
        if r < 0.01:
            lines.append(f"{t} disconnect")
            connected = deadman = fresh = False
            mark(t)
            t += rng.randint(100, 3000)
            lines.append(f"{t} connect Soak Pad")
            connected = True
            if rng.random() < 0.3:  # a deadman stuck at connect: not a fresh press
                lines.append(f"{t} button leftshoulder 1")
                deadman = True
        elif r < 0.15:
            deadman = not deadman
            lines.append(f"{t} button leftshoulder {int(deadman)}")
            if deadman:
                fresh = True
        elif r < 0.55:
            axis = rng.choice(["leftx", "lefty", "rightx", "righty", "lefttrigger", "righttrigger"])
            lo = 0 if "trigger" in axis else -32768
            lines.append(f"{t} axis {axis} {rng.randint(lo, 32767)}")
        else:
            button = rng.choice(["a", "b", "x", "y", "back", "start", "dpup", "dpdown", "dpleft",
                                 "dpright", "rightshoulder", "leftstick", "rightstick"])
            lines.append(f"{t} button {button} 1")
            if rng.random() < 0.7:  # most buttons are let go, some only after a while
                lines.append(f"{t + rng.choice([0, 3, 60, 400])} button {button} 0")
        mark(t)
        lines.sort(key=lambda l: int(l.split()[0]))  # releases may land after later events
    lines.append(f"{end} end")
    mark(end)
    if since is not None:
        may_move.append((since, end))
    with open(path, "w") as f:
        f.write("# soak script (scripts/soak.py)\n" + "\n".join(lines) + "\n")
    return may_move


def vm_kb(pid, field):
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith(field + ":"):
                    return int(line.split()[1])
    except OSError:
        pass
    return None


def log_reader(fd, path, close_after, started, result):
    """Reads the bridge's log pipe into path; closes the pipe close_after seconds after started."""
    with open(path, "wb") as out:
        while time.monotonic() - started < close_after:
            if select.select([fd], [], [], 0.2)[0]:
                chunk = os.read(fd, 65536)
                if not chunk:
                    break
                out.write(chunk)
    os.close(fd)
    result["closed_at"] = time.monotonic() - started


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seconds", type=int, default=3600)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--robot", default="hd1")
    ap.add_argument("--code", default="01")
    ap.add_argument("--bin", default=os.path.join(os.path.dirname(__file__), "..", "build", "src", "andros-bridge"))
    ap.add_argument("--keep", help="folder to keep the script, capture and decoded frames in")
    ap.add_argument("--close-log-after", type=float, metavar="SECONDS",
                    help="pipe the bridge's stdout and stderr through a reader that closes its end after SECONDS")
    a = ap.parse_args()

    work = a.keep or tempfile.mkdtemp(prefix="andros-soak-")
    os.makedirs(work, exist_ok=True)
    script = os.path.join(work, "soak.events")
    may_move = make_script(script, a.seconds, random.Random(a.seed))
    catalogue = [json.loads(l) for l in subprocess.check_output([a.bin, "frame", "signals", "--json"]).splitlines()]
    pairs = {(s["name"], s["partner"]) for s in catalogue if s["partner"]}
    kinds = {s["name"]: s["kind"] for s in catalogue}

    master, slave = pty.openpty()
    tty.setraw(master)
    tty.setraw(slave)
    port = os.ttyname(slave)
    started = time.monotonic()
    argv = [a.bin, "run", "--robot", a.robot, "--port", port, "--code", a.code, "--input", script]
    log_path = os.path.join(work, "bridge.log")
    log_pipe = {}
    if a.close_log_after is None:
        proc = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=open(log_path, "w"))
        reader = None
    else:
        r, w = os.pipe()
        proc = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=w, stderr=w)
        os.close(w)
        reader = threading.Thread(target=log_reader, args=(r, log_path, a.close_log_after, started, log_pipe))
        reader.start()
    capture, arrivals, pending = bytearray(), [], bytearray()
    rss_start = rss_end = None
    next_report = started + 60
    while True:
        r, _, _ = select.select([master], [], [], 0.2)
        now = time.monotonic()
        if r:
            chunk = os.read(master, 4096)
            capture += chunk
            pending += chunk
            while len(pending) >= 36:  # the bridge writes whole frames: one timestamp per frame
                i = pending.find(b"\xf1\xf1")
                if i < 0:
                    pending.clear()
                    break
                if len(pending) < i + 36:
                    break
                arrivals.append(now)
                del pending[:i + 36]
        if rss_start is None and now - started > 5:
            rss_start = vm_kb(proc.pid, "VmRSS")
        if now - started < a.seconds - 5:
            rss_end = vm_kb(proc.pid, "VmRSS") or rss_end
        if now >= next_report:
            print(f"  {int(now - started)} s: {len(arrivals)} frames", file=sys.stderr, flush=True)
            next_report += 60
        if proc.poll() is not None and not r:
            break
    exit_code = proc.wait()
    if reader:
        reader.join()
    os.close(master)
    os.close(slave)

    with open(os.path.join(work, "capture.bin"), "wb") as f:
        f.write(capture)
    decoded = subprocess.run([a.bin, "frame", "decode", "--code", a.code, os.path.join(work, "capture.bin")],
                             capture_output=True, text=True, check=True)
    frames = [json.loads(l) for l in decoded.stdout.splitlines()]
    t0 = arrivals[0] if arrivals else started

    violations = {"invalid": 0, "opposing pair": 0, "weapon bit": 0, "safety 0 but not neutral": 0,
                  "moving while not enabled": 0}
    examples = []
    starts = [s for s, _ in may_move]

    def allowed(t_ms):
        k = bisect.bisect_right(starts, t_ms) - 1
        return k >= 0 and may_move[k][0] <= t_ms <= may_move[k][1]

    def neutral(s):
        return all(v == 0 for n, v in s.items() if kinds[n] in ("motion", "weapon", "interlock")) and \
            s["drive"] == 128 and s["pivot"] == 128

    for k, f in enumerate(frames):
        s = f["signals"]
        broke = []
        if not f["valid"]:
            broke.append("invalid")
        if any(s[x] and s[y] for x, y in pairs):
            broke.append("opposing pair")
        if any(s[n] for n, kind in kinds.items() if kind == "weapon"):
            broke.append("weapon bit")
        if s["safety"] == 0 and not neutral(s):
            broke.append("safety 0 but not neutral")
        # The frame's tick on the bridge's clock, from when it arrived (a skipped
        # tick must not shift every later frame).
        t_ms = round((arrivals[k] - t0) * 1000 / PERIOD_MS) * PERIOD_MS if len(arrivals) == len(frames) \
            else k * PERIOD_MS
        margin = 2 * PERIOD_MS
        if not allowed(t_ms - margin) and not allowed(t_ms) and not allowed(t_ms + margin) and not neutral(s):
            broke.append("moving while not enabled")
        for b in broke:
            violations[b] += 1
        if broke and len(examples) < 5:
            examples.append((k, broke, f["data"]))

    periods = [(b - a_) * 1000 for a_, b in zip(arrivals, arrivals[1:])]
    span_min = (arrivals[-1] - t0) / 60 if len(arrivals) > 1 else 0
    drift_ms = ((arrivals[-1] - t0) * 1000 - (len(arrivals) - 1) * PERIOD_MS) if len(arrivals) > 1 else 0
    dev = sorted(abs(p - PERIOD_MS) for p in periods)
    enabled = sum(1 for f in frames if f["signals"]["safety"])
    neutral_end = len(frames) >= 3 and all(neutral(f["signals"]) for f in frames[-3:])
    print(f"soak: {a.seconds} s, seed {a.seed}, robot {a.robot}, bridge exit {exit_code}")
    print(f"frames sent (decoded): {len(frames)}  enabled: {enabled}  moving: "
          f"{sum(1 for f in frames if f['signals']['drive'] != 128 or f['signals']['pivot'] != 128)}")
    print(f"decoder: {decoded.stderr.strip()}")
    print(f"invalid frames: {violations['invalid']}")
    print("safety violations: " + ", ".join(f"{k} {v}" for k, v in violations.items() if k != "invalid"))
    if periods:
        print(f"period: median {statistics.median(periods):.3f} ms, p99 deviation {dev[int(0.99 * (len(dev) - 1))]:.3f} ms, "
              f"max deviation {dev[-1]:.3f} ms")
        print(f"drift: {drift_ms:+.2f} ms over {span_min:.1f} min ({drift_ms / max(span_min, 1e-9):+.3f} ms/min)")
    print(f"RSS: {rss_start} KiB at 5 s, {rss_end} KiB near the end")
    if reader:
        print(f"log pipe: its reader closed it {log_pipe.get('closed_at', 0):.1f} s in; "
              f"{os.path.getsize(log_path)} bytes of log read before that")
    print(f"end: the last 3 frames are neutral: {'yes' if neutral_end else 'NO'}")
    for k, broke, data in examples:
        print(f"  frame {k}: {', '.join(broke)}: {data}")
    print(f"files in {work}")
    bad = sum(violations.values())
    sys.exit(0 if bad == 0 and exit_code == 0 and neutral_end else 1)


if __name__ == "__main__":
    main()
