#!/usr/bin/env python3
"""The bridge process's steady-state cost at 25 Hz with SDL input (no
controller attached: SDL initialised, the event queue drained every tick) on a
pseudo-terminal: CPU from /proc/PID/stat between 5 s and 5 + SECONDS s after
start, so start-up (SDL_Init, device enumeration) is left out, and RSS.

  bench/steady_cost.py BIN [SECONDS] [extra run flags...]
"""
import os, pty, select, signal, subprocess, sys, time, tty

binary = sys.argv[1]
seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 30
extra = sys.argv[3:] or ["--input", "sdl"]
master, slave = pty.openpty()
tty.setraw(master)
proc = subprocess.Popen([binary, "run", "--port", os.ttyname(slave)] + extra, stdin=subprocess.DEVNULL,
                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                        env=dict(os.environ, SDL_VIDEODRIVER="dummy"))
ticks = os.sysconf("SC_CLK_TCK")


def cpu_s():
    fields = open(f"/proc/{proc.pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / ticks


def status_mb(field):
    for line in open(f"/proc/{proc.pid}/status"):
        if line.startswith(field + ":"):
            return int(line.split()[1]) / 1024


def read_for(s):
    end, got = time.monotonic() + s, 0
    while time.monotonic() < end:
        if select.select([master], [], [], 0.2)[0]:
            got += len(os.read(master, 4096))
    return got


read_for(5)
c0, t0 = cpu_s(), time.monotonic()
frames = read_for(seconds) // 36
c1, t1 = cpu_s(), time.monotonic()
rss, peak = status_mb("VmRSS"), status_mb("VmHWM")
proc.send_signal(signal.SIGINT)
read_for(1)
proc.wait()
share = 100 * (c1 - c0) / (t1 - t0)
print(f"| steady state at 25 Hz, {' '.join(extra)}, --port PTY | {share:.2f}% of a core over {t1 - t0:.0f} s "
      f"({frames} frames), RSS {rss:.1f} MB, peak {peak:.1f} MB | < 0.5%, < 12 MB | "
      f"{'PASS' if share < 0.5 and peak < 12 else 'FAIL'} |")
