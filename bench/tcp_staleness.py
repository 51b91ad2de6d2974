#!/usr/bin/env python3
"""How old can a command be when a TCP serial server finally delivers it?

  bench/tcp_staleness.py BIN [--seconds S] [--only NAME]

Runs `BIN run --port tcp:127.0.0.1:PORT --input SCRIPT` against a server on
127.0.0.1 that misbehaves as a hung ser2net or a stalling radio modem would,
and reports, for every frame the server's program finally reads, how long
after its tick it arrived. Frames carry no timestamp, so the script moves
both sticks every tick (drive and pivot take a new pair of values each
period); `BIN replay` of the same script says which tick each frame belongs
to, and only frames whose bytes occur once are counted.

Scenarios (each with the kernel's default receive buffer, which grows on its
own, and with a fixed 4 kB one, as an embedded serial server has):
  stall  the server reads for 3 s, stops reading (and accepting) for S s,
         then reads everything, oldest connection first
  slow   the server reads one frame every 80 ms (half the frame rate)
"""
import argparse, os, select, signal, socket, subprocess, sys, tempfile, time

PERIOD_MS = 40


def write_script(path, seconds):
    lines = ["0 connect Bench pad", "20 button leftshoulder 1"]
    for k in range(1, seconds * 1000 // PERIOD_MS):
        t = k * PERIOD_MS
        lines.append(f"{t} axis lefty {-32768 + (k % 160) * 409}")
        lines.append(f"{t} axis leftx {-32768 + (k // 160 % 160) * 409}")
    lines.append(f"{seconds * 1000} end")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def tick_of_frame(binary, script):
    """frame hex -> its time in ms, for frames that occur once."""
    out = subprocess.run([binary, "replay", script, "--robot", "hd1", "--format", "hex"],
                         check=True, capture_output=True, text=True).stdout
    seen = {}
    for line in out.splitlines():
        t, frame = line.split()
        seen.setdefault(frame, []).append(int(t))
    # From the first tick the deadman holds on: the neutral frame before it is also sent at shutdown.
    return {f: ts[0] for f, ts in seen.items() if len(ts) == 1 and ts[0] >= PERIOD_MS}


def frames_in(buf):
    """Splits whole 36-byte frames (F1 F1 ...) off the front of buf."""
    out = []
    while True:
        i = buf.find(b"\xf1\xf1")
        if i < 0 or len(buf) - i < 36:
            return out, buf[max(i, 0):] if i >= 0 else b""
        out.append(bytes(buf[i:i + 36]))
        buf = buf[i + 36:]


def serve(lst, mode, stall_for, stop_at):
    """Runs the misbehaving server until stop_at; returns [(arrival, frame)]."""
    conns, bufs, got = [], {}, []
    start = time.monotonic()
    next_read = start
    while time.monotonic() < stop_at:
        now = time.monotonic()
        stalled = mode == "stall" and 3 <= now - start < 3 + stall_for
        if stalled:
            time.sleep(0.01)
            continue
        r, _, _ = select.select([lst] + conns, [], [], 0.01)
        if lst in r:
            c, _ = lst.accept()
            conns.append(c)
            bufs[c] = b""
        # Oldest connection first, as a serial server serving one client at a time would.
        for c in list(conns):
            if c not in r:
                continue
            if mode == "slow":
                if now < next_read:
                    break
                next_read = max(next_read + 0.08, now - 0.08)
            try:
                data = c.recv(36 if mode == "slow" else 65536)
            except OSError:
                data = b""
            if not data:
                conns.remove(c)
                c.close()
                continue
            frames, bufs[c] = frames_in(bufs[c] + data)
            got += [(time.monotonic(), f.hex().upper()) for f in frames]
            break
    for c in conns:
        c.close()
    return got


def scenario(binary, script, ticks, mode, rcvbuf, seconds):
    lst = socket.socket()
    if rcvbuf:
        lst.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, rcvbuf)
    lst.bind(("127.0.0.1", 0))
    lst.listen(8)
    port = lst.getsockname()[1]
    err = tempfile.TemporaryFile()
    proc = subprocess.Popen([binary, "run", "--port", f"tcp:127.0.0.1:{port}", "--input", script],
                            stdout=subprocess.DEVNULL, stderr=err)
    stall_for = seconds - 8
    got = serve(lst, mode, stall_for, time.monotonic() + seconds + 4)
    if proc.poll() is None:
        proc.send_signal(signal.SIGTERM)
    code = proc.wait()
    err.seek(0)
    log = err.read().decode()
    timed = [(a, ticks[f]) for a, f in got if f in ticks]
    base = min(a - t / 1000 for a, t in timed)
    ages = [a - base - t / 1000 for a, t in timed]
    worst = max(ages)
    stale = sum(1 for x in ages if x > 0.5)
    stalls = log.count("stalled")
    print(f"{mode:5} rcvbuf {'default' if not rcvbuf else rcvbuf:>7}: {len(got):5} frames read, "
          f"worst age {worst:6.2f} s, {stale:4} older than 0.5 s, stalls detected {stalls}, exit {code}")
    return worst


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("--seconds", type=int, default=28, help="length of each run (the stall is this - 8 s)")
    ap.add_argument("--only", choices=["stall", "slow"])
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        script = os.path.join(tmp, "moving.events")
        write_script(script, a.seconds)
        ticks = tick_of_frame(a.binary, script)
        print(f"{len(ticks)} distinct frames in a {a.seconds} s script; ages relative to the freshest delivery")
        for mode in ["stall", "slow"]:
            if a.only and mode != a.only:
                continue
            for rcvbuf in [0, 4096]:
                scenario(a.binary, script, ticks, mode, rcvbuf, a.seconds)


if __name__ == "__main__":
    main()
