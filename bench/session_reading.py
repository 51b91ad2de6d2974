#!/usr/bin/env python3
"""What reading a session costs (docs/recording.md, "Reading bounds"): each
reader (verify, sessions, replay, plot, export) on sessions made by
tests/cli/session_tool.py, its wall time and peak memory (max RSS).

  bench/session_reading.py BIN [MB]      (default 98: the grown session's size)

The sessions: the drive session grown to MB with a stick moving on every tick
(an event and a frame record a tick: a drive's worst case; the frames are
not the loop's, so replay differs early but runs every tick all the same);
the same with 50 reloads; a link flapping every second for 2 h and 6 h; a
crafted 10 kB one asking for 24 h at 320 Hz, in format 2 (read as before,
bounded by 24 h) and 3 (refused at once); and a folder of ten 10 MB sessions
for `sessions`, which replays each. Prints a Markdown table.
"""
import os, resource, subprocess, sys, tempfile, time

binary = os.path.abspath(sys.argv[1])
mb = int(sys.argv[2]) if len(sys.argv) > 2 else 98
here = os.path.dirname(os.path.abspath(__file__))
tool = os.path.join(here, "..", "tests", "cli", "session_tool.py")
drive = os.path.join(here, "..", "tests", "data", "sessions", "drive.andros-session")
tmp = tempfile.mkdtemp(prefix="andros-bench-read-")


def made(name, *args):
    path = os.path.join(tmp, name + ".andros-session")
    subprocess.run([sys.executable, tool] + [a if a != "OUT" else path for a in args], check=True)
    return path


def measure(*args):
    """Wall seconds and peak MB of one run of BIN args (output discarded), and its first line of output."""
    start = time.monotonic()
    p = subprocess.Popen([binary] + list(args), stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    first = p.stdout.readline().decode(errors="replace").strip()
    for _ in iter(lambda: p.stdout.read(1 << 20), b""):
        pass
    _, _, usage = os.wait4(p.pid, 0)
    return time.monotonic() - start, usage.ru_maxrss / 1024, first[:90]


grown = made("grown", "grow", drive, str(mb), "OUT")
sessions = {
    f"grown, {mb} MB": grown,
    f"grown, {mb} MB, 50 reloads": made("reloads", "reloads", drive, "50", str(mb), "OUT"),
    "link flapping every second, 2 h": made("flaps2", "flaps", drive, "2", "OUT"),
    "link flapping every second, 6 h": made("flaps6", "flaps", drive, "6", "OUT"),
    "10 kB, 24 h at 320 Hz, format 2": made("long2", "long", drive, "24", "320", "2", "OUT"),
    "10 kB, 24 h at 320 Hz, format 3": made("long3", "long", drive, "24", "320", "3", "OUT"),
}
print("| session | size | command | time | memory | says |")
print("|---|---|---|---|---|---|")
for what, path in sessions.items():
    size = os.path.getsize(path) / 1e6
    commands = [["verify", path], ["replay", path], ["plot", path, "--output", os.path.join(tmp, "p.svg")],
                ["export", path, "--output", os.path.join(tmp, "e.csv")]]
    if "format 2" in what:
        commands = commands[:2]  # export: 27.6 M rows, 4.6 GB; plot as the others
    for cmd in commands:
        t, rss, first = measure(*cmd)
        print(f"| {what} | {size:.2f} MB | {cmd[0]} | {t:.2f} s | {rss:.0f} MB | {first} |", flush=True)
    for f in ("p.svg", "e.csv"):
        if os.path.exists(os.path.join(tmp, f)):
            os.remove(os.path.join(tmp, f))
folder = os.path.join(tmp, "folder")
os.mkdir(folder)
ten = made("ten", "grow", drive, "10", "OUT")
for i in range(10):
    os.link(ten, os.path.join(folder, f"2024010{i}-000000-{i}.andros-session"))
t, rss, _ = measure("sessions", "--record-dir", folder)
print(f"| ten sessions of 10 MB (a folder) | 100 MB | sessions | {t:.2f} s | {rss:.0f} MB | each replayed |")
subprocess.run(["rm", "-rf", tmp])
