#!/usr/bin/env python3
"""A session's plot draws the frames the session recorded, whatever the run
met (ticks a loaded machine skipped, frames a busy link refused): the drive
and pivot lines are rebuilt here from the session's frame records and
compared, point by point, with the page's (each reduced to its shape: the
points where the value changes, and a line's ends).

  check_plot.py BIN SESSION SVG FROM_S TO_S

The page's own drive box (its rectangle) gives the scale; a line has, for
each pixel column, the lowest and the highest value sent in it, and breaks
where a tick sent nothing (docs/recording.md, "Plot"). Exit 1 with the first
difference."""
import json, math, re, subprocess, sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from session_lib import ticks

BIN, SESSION, SVG, FROM_S, TO_S = sys.argv[1:6]
start, to = round(float(FROM_S) * 1000), round(float(TO_S) * 1000)
page = open(SVG, encoding="utf-8").read()
box = re.search(r'<rect x="([\d.]+)" y="([\d.]+)" width="([\d.]+)" height="([\d.]+)" fill="none"', page)
left, top, width, height = map(float, box.groups())
catalogue = [json.loads(l) for l in subprocess.check_output([BIN, "frame", "signals", "--json"]).splitlines()]
byte = {s["name"]: s["byte"] for s in catalogue}


def column(t_ms):
    return math.floor(left + width * (t_ms - start) / (to - start) + 0.5)


def expected(index):
    """The line's points, as [[(column, value)...] per unbroken stretch]."""
    lines, current, col, lo, hi = [], [], None, 0, 0
    for t in ticks(SESSION):
        if not start <= t.t_ms <= to:
            continue
        if t.result != "sent":
            if col is not None:
                current += [(col, lo)] + ([(col, hi)] if hi != lo else [])
            lines += [current] if current else []
            current, col = [], None
            continue
        v, c = t.data[index], column(t.t_ms)
        if c != col:
            if col is not None:
                current += [(col, lo)] + ([(col, hi)] if hi != lo else [])
            col, lo, hi = c, v, v
        else:
            lo, hi = min(lo, v), max(hi, v)
    if col is not None:
        current += [(col, lo)] + ([(col, hi)] if hi != lo else [])
    return lines + ([current] if current else [])


def drawn(d):
    """The path's points, the y coordinates turned back into values."""
    lines = []
    for part in d.split("M")[1:]:
        points = [p.split() for p in part.split("L")]
        lines.append([(int(x), (top + height - float(y)) * 255 / height) for x, y in points])
    return lines


paths = re.findall(r'<path d="([^"]*)"', page)
if len(paths) != 2:
    sys.exit(f"{SVG}: {len(paths)} paths, expected drive's and pivot's")
def shape(lines):
    """A line's shape: a point in the middle of a level run (the same value
    as the points on both sides of it) says nothing. The page draws a
    session from its records' change points, not a point a column."""
    out = []
    for pts in lines:
        out.append([p for i, p in enumerate(pts)
                    if i in (0, len(pts) - 1) or not abs(pts[i - 1][1] - p[1]) < 0.3 > abs(pts[i + 1][1] - p[1])])
    return out


for name, d in zip(("drive", "pivot"), paths):
    want, got = shape(expected(byte[name])), shape(drawn(d))
    flat_want = [(i, p) for i, line in enumerate(want) for p in line]
    flat_got = [(i, p) for i, line in enumerate(got) for p in line]
    if len(flat_want) != len(flat_got):
        sys.exit(f"{name}: {len(flat_got)} points in {len(got)} lines drawn, the session's frames make "
                 f"{len(flat_want)} in {len(want)}")
    for (i, (c, v)), (j, (gc, gv)) in zip(flat_want, flat_got):
        if i != j or c != gc or abs(v - gv) > 0.3:
            sys.exit(f"{name}: drawn ({gc}, {gv:.1f}) in line {j}, the session has ({c}, {v}) in line {i}")
    if not flat_want:
        sys.exit(f"{name}: the session sent no frame between {FROM_S} and {TO_S} s")
print("the plot's drive and pivot lines are the session's frames")
