#!/usr/bin/env python3
"""Writes the largest mapping the documented limits allow (docs/mapping.md):
a chain of 16 files (the one loaded and 15 bases), together just under the
100,000 YAML nodes, each file binding the same inputs again, so that every
`extends` replaces every binding of its base. Then times `check` on it and
`run` (start, the script's 4 frames, stop): wall time and CPU time (user +
system), the latter the same on a busy machine.

  bench/mapping_chain.py BIN DIR [--runs N]

DIR gets chain0.yaml (robot: HD1, the one to load) ... chain15.yaml.
"""
import os, resource, statistics, subprocess, sys, time

FILES = 16
MAX_NODES = 100_000
# Inputs one list may bind, each once: joystick buttons 0..255, hat directions.
INPUTS = [str(n) for n in range(256)] + [f"hat{h}{d}" for h in range(64) for d in ("up", "down", "left", "right")]
SIGNALS = ["tool_on", "front_art_up", "rear_art_up", "zoom_up", "focus_up", "iris_up", "fiber_takeup"]
LAYERS = ["a", "b", "x", "y"]  # layer names and their hold buttons (pad buttons: no clash with the inputs)
NODES_PER_BINDING = 5  # {signal: S, button: B}: the map, two keys, two values


def binding(i, sig, indent=""):
    return f"{indent}  - signal: {SIGNALS[(i + sig) % len(SIGNALS)]}\n{indent}    button: {INPUTS[i]}\n"


def write_chain(out_dir, spare=600):
    # The files' own keys, lists and layers take 35 nodes each (560); the rest is bindings.
    per_file = (MAX_NODES - spare) // FILES // NODES_PER_BINDING
    lists = [per_file // (len(LAYERS) + 1)] * (len(LAYERS) + 1)
    lists[0] += per_file - sum(lists)
    for f in range(FILES):
        text = ""
        if f == 0:
            text += "robot: HD1\ndeadman: leftshoulder\n"
        if f + 1 < FILES:
            text += f"extends: chain{f + 1}.yaml\n"
        text += "bindings:\n" + "".join(binding(i, f) for i in range(lists[0]))
        text += "layers:\n"
        for n, name in enumerate(LAYERS):
            text += f"  {name}:\n    hold: {name}\n    bindings:\n"
            text += "".join(binding(i, f + n, "    ") for i in range(lists[n + 1]))
        with open(os.path.join(out_dir, f"chain{f}.yaml"), "w") as fh:
            fh.write(text)
    return per_file * FILES


def cpu_of_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed(cmd, runs, **kw):
    """Wall and CPU seconds of each run."""
    wall, cpu = [], []
    for _ in range(runs):
        t, c = time.monotonic(), cpu_of_children()
        p = subprocess.run(cmd, capture_output=True, text=True, **kw)
        wall.append(time.monotonic() - t)
        cpu.append(cpu_of_children() - c)
        if p.returncode != 0:
            sys.exit(f"{' '.join(cmd)}: exit {p.returncode}: {p.stderr.strip()}")
    return wall, cpu


def summary(name, times, runs):
    wall, cpu = times
    return (f"{name}: wall median {statistics.median(wall):.3f} s (min {min(wall):.3f}, max {max(wall):.3f}), "
            f"CPU median {statistics.median(cpu):.3f} s, over {runs} runs")


def main():
    bin_, out_dir = sys.argv[1], sys.argv[2]
    runs = int(sys.argv[sys.argv.index("--runs") + 1]) if "--runs" in sys.argv else 5
    os.makedirs(out_dir, exist_ok=True)
    bindings = write_chain(out_dir)
    loaded = os.path.join(out_dir, "chain0.yaml")
    size = sum(os.path.getsize(os.path.join(out_dir, f"chain{f}.yaml")) for f in range(FILES))
    print(f"{FILES} files, {bindings} bindings, {size // 1024} KiB", flush=True)
    check = timed([bin_, "check", loaded], runs)
    # run: from exec to its first frame; the script ends at once (then 3 neutral frames, drain, exit).
    script = os.path.join(out_dir, "end.events")
    with open(script, "w") as fh:
        fh.write("0 connect Pad\n0 end\n")
    env = dict(os.environ, XDG_CONFIG_HOME=out_dir)
    start = timed([bin_, "run", "--mapping", loaded, "--input", script, "--port", "sim"], runs, env=env)
    print(summary("check", check, runs))
    print(summary("run (start, 4 frames, stop)", start, runs))


if __name__ == "__main__":
    main()
