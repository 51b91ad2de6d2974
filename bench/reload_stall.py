#!/usr/bin/env python3
"""Does a reload of the largest mapping the limits allow stall the frame loop?

  bench/reload_stall.py BIN DIR [--reloads N]

Writes the 16-file extends chain of bench/mapping_chain.py into DIR, runs
`BIN run` on it into a pseudo-terminal under a fake service manager
(NOTIFY_SOCKET, WATCHDOG_USEC=1 s as the unit sets), sends SIGHUP N times a
second apart, and prints the longest gap between frames on the port and
between WATCHDOG=1 pings, over the whole run and around the reloads. The
loop must keep its 40 ms period through a reload (the files are read on a
worker thread) and the pings must stay far inside the watchdog's 1 s.
"""
import os, select, signal, socket, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(__file__))
from mapping_chain import write_chain  # noqa: E402


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    binary, out_dir = sys.argv[1], sys.argv[2]
    reloads = int(sys.argv[sys.argv.index("--reloads") + 1]) if "--reloads" in sys.argv else 5
    os.makedirs(out_dir, exist_ok=True)
    write_chain(out_dir)
    script = os.path.join(out_dir, "idle.events")
    with open(script, "w") as f:
        f.write("0 connect pad\n60000 end\n")
    master, slave = os.openpty()
    port = os.ttyname(slave)
    sock_path = os.path.join(tempfile.mkdtemp(), "notify")
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
    sock.bind(sock_path)
    env = dict(os.environ, NOTIFY_SOCKET=sock_path, WATCHDOG_USEC="1000000")
    proc = subprocess.Popen([binary, "run", "--port", port, "--mapping", os.path.join(out_dir, "chain0.yaml"),
                             "--input", script], env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    env.pop("WATCHDOG_PID", None)
    frames, pings, hups = [], [], []
    start = time.monotonic()
    next_hup = start + 1.5
    while time.monotonic() - start < 1.5 + reloads + 1.0:
        r, _, _ = select.select([master, sock], [], [], 0.005)
        now = time.monotonic()
        if master in r:
            os.read(master, 4096)
            frames.append(now)
        if sock in r:
            if b"WATCHDOG=1" in sock.recv(4096):
                pings.append(now)
        if len(hups) < reloads and now >= next_hup:
            proc.send_signal(signal.SIGHUP)
            hups.append(now)
            next_hup += 1.0
    proc.send_signal(signal.SIGTERM)
    err = proc.communicate(timeout=10)[1].decode()
    reloaded = err.count("reloaded")

    def gaps(times, lo=0.0, hi=1e18):
        g = [b - a for a, b in zip(times, times[1:]) if lo <= b <= hi]
        return max(g) * 1000 if g else float("nan")

    around = max(gaps(frames, h, h + 0.8) for h in hups)
    print(f"reloads: {len(hups)} SIGHUP, {reloaded} 'reloaded' in the log, exit {proc.returncode}")
    print(f"frames:  {len(frames)} arrivals; longest gap {gaps(frames[10:]):.1f} ms overall, "
          f"{around:.1f} ms in the 0.8 s after a SIGHUP")
    print(f"pings:   {len(pings)} WATCHDOG=1; longest gap {gaps(pings):.1f} ms (the watchdog fires at 1000 ms)")


if __name__ == "__main__":
    main()
