#!/usr/bin/env python3
"""Does the trainer's web server ever hold up the frame loop?

  bench/trainer_clients.py BIN [--seconds S]

Runs `BIN trainer` on a drive script and, in one run, three phases of S
seconds each (default 20): no web client but the measuring one; 8 clients
reading GET /events; the same 8 and one stalled client (it asks for
/events, then never reads, with a 4 kB receive buffer). The measuring
client reads /events too: every object carries the time the loop handed its
tick over after sending the frame ("sent", seconds to the microsecond,
monotonic), so the gaps between objects are the loop's ticks as they
happened. Reports, per phase, the p50, p99
and largest |gap - 40 ms|, and frames seen; and whether the stalled client
was dropped (the server closed it)."""
import argparse, json, os, socket, subprocess, sys, tempfile, threading, time

PERIOD_MS = 40


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def write_script(path, seconds):
    """The deadman held, the vehicle driving slow circles, every tick a little different."""
    lines = ["0 connect Bench pad", "100 button leftshoulder 1"]
    for k in range(5, seconds * 1000 // 200):
        lines.append(f"{k * 200} axis lefty {-20000 + (k % 20) * 100}")
        lines.append(f"{k * 200} axis leftx {8000 + (k % 7) * 100}")
    lines.append(f"{seconds * 1000} end")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def open_stream(port, rcvbuf=0):
    s = socket.socket()
    if rcvbuf:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, rcvbuf)
    s.connect(("127.0.0.1", port))
    s.sendall(f"GET /events HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n\r\n".encode())
    return s


def reader(port, stop):
    s = open_stream(port)
    while not stop.is_set():
        if not s.recv(65536):
            break
    s.close()


def percentile(values, p):
    v = sorted(values)
    return v[min(len(v) - 1, int(p / 100 * len(v)))] if v else float("nan")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("bin")
    ap.add_argument("--seconds", type=int, default=20)
    a = ap.parse_args()
    port = free_port()
    tmp = tempfile.mkdtemp()
    script = os.path.join(tmp, "drive.events")
    write_script(script, 3 * a.seconds + 6)
    env = dict(os.environ, XDG_STATE_HOME=tmp, XDG_CONFIG_HOME=tmp)
    trainer = subprocess.Popen([a.bin, "trainer", "--listen", f"127.0.0.1:{port}", "--input", script,
                                "--exit-at-end"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    time.sleep(1.5)
    phase = ["warm-up"]
    times = {}
    measurer = open_stream(port)
    done = threading.Event()

    def measure():
        buf = b""
        while not done.is_set():
            chunk = measurer.recv(65536)
            if not chunk:
                break
            buf += chunk
            while b"\n\n" in buf:
                event, buf = buf.split(b"\n\n", 1)
                for line in event.split(b"\n"):
                    if line.startswith(b"data: "):
                        times.setdefault(phase[0], []).append(json.loads(line[6:])["sent"])

    threading.Thread(target=measure, daemon=True).start()
    time.sleep(2)
    stop_readers = threading.Event()
    phase[0] = "0 clients"
    time.sleep(a.seconds)
    readers = [threading.Thread(target=reader, args=(port, stop_readers), daemon=True) for _ in range(8)]
    for r in readers:
        r.start()
    phase[0] = "8 clients"
    time.sleep(a.seconds)
    stalled = open_stream(port, rcvbuf=4096)
    phase[0] = "8 clients + 1 stalled"
    time.sleep(a.seconds)
    phase[0] = "end"
    stop_readers.set()
    stalled.settimeout(3)
    dropped = False
    try:
        while True:
            if not stalled.recv(65536):
                dropped = True
                break
    except socket.timeout:
        pass
    done.set()
    trainer.wait(timeout=3 * a.seconds + 30)
    print(f"trainer: {a.seconds} s a phase, exit {trainer.returncode}")
    for name in ["0 clients", "8 clients", "8 clients + 1 stalled"]:
        t = times.get(name, [])
        dev = [abs((b - c) * 1000 - PERIOD_MS) for c, b in zip(t, t[1:])]
        print(f"  {name:22} frames {len(t):5}  |gap - 40 ms|: p50 {percentile(dev, 50):6.3f} ms"
              f"  p99 {percentile(dev, 99):6.3f} ms  max {max(dev) if dev else float('nan'):6.3f} ms")
    print(f"  the stalled client was {'dropped (the server closed it)' if dropped else 'NOT dropped'}")


if __name__ == "__main__":
    main()
