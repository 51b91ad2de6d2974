#!/usr/bin/env python3
"""The run's cost with the flight recorder and without it (--no-record): the
same script, whose left stick moves on every tick (a frame record each tick,
the recorder's worst case), through steady_cost.py (CPU between 5 s and
5 + SECONDS s after start, RSS), sessions in a temporary folder.

  bench/recorder_cost.py BIN [SECONDS]      (default 20)
"""
import os, subprocess, sys, tempfile

binary = sys.argv[1]
seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 20
here = os.path.dirname(os.path.abspath(__file__))
tmp = tempfile.mkdtemp(prefix="andros-bench-rec-")
script = os.path.join(tmp, "busy.events")
end_ms = int((seconds + 10) * 1000)
with open(script, "w") as f:
    f.write("0 connect pad\n0 button leftshoulder 0\n100 button leftshoulder 1\n")
    for t in range(200, end_ms, 40):
        f.write(f"{t} axis lefty {-2000 - (t * 7) % 30000}\n")
    f.write(f"{end_ms} end\n")
env = dict(os.environ, XDG_STATE_HOME=os.path.join(tmp, "state"), XDG_CONFIG_HOME=os.path.join(tmp, "xdg"))
for extra in (["--input", script], ["--input", script, "--no-record"]):
    subprocess.run([sys.executable, os.path.join(here, "steady_cost.py"), binary, str(seconds)] + extra, env=env,
                   check=True)
sessions = [os.path.join(env["XDG_STATE_HOME"], "andros-bridge", n)
            for n in os.listdir(os.path.join(env["XDG_STATE_HOME"], "andros-bridge"))]
size = sum(os.path.getsize(p) for p in sessions)
print(f"| session written in {seconds + 5:.0f}+ s of a stick moving every tick | {size / 1e3:.0f} kB "
      f"({size / 1e6 * 3600 / (seconds + 5):.1f} MB an hour) | | |")
subprocess.run(["rm", "-rf", tmp])
