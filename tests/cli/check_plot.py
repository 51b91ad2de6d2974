#!/usr/bin/env python3
"""A session's plot draws what the session recorded, and nothing that did
not happen (docs/recording.md, "Plot"), read back from the page and compared
with the session's own records:

  check_plot.py BIN SESSION SVG FROM_S TO_S [STOP_BUTTON]

FROM_S and TO_S are the range the page was asked for (TO_S `last`: no
--to, to the session's last tick); STOP_BUTTON the stop button of the
operator's and the supervisor's mapping (`guide`), whose every press must
show on its lane.

- The drive and pivot lines: each frame sent holds its value until the next
  tick's (a step). Along each line the points are in time order; in each
  pixel column the values drawn, in the order drawn, are values that held in
  that column, in the order they held, and include its lowest and highest;
  from one column to another the line is level, at a value that held in
  every column it crosses; a line breaks where a tick sent nothing, and
  starts and ends where the frames do (at the page's edges when they held
  on past them).
- The state band: from the left edge, the state in effect at FROM_S, then a
  band where each state began, to the last tick or TO_S; a reset's tick
  where it was reset, none for a reset outside the range.
- The labels on the band and above it overlap none other on their row, and
  a stop's stays within its band: each measured with the advance widths of
  DejaVu Sans, the page's font.
- Each press of a stop button in the range is a mark on its lane, at least
  2 px wide.
- The page's count of ticks is of those the session ran in the range.

Exit 1 with the first difference."""
import json, math, re, struct, subprocess, sys
import xml.etree.ElementTree as ET

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from session_lib import records, rate_millihertz, ticks

BIN, SESSION, SVG, FROM_S, TO_S = sys.argv[1:6]
STOP_BUTTON = sys.argv[6] if len(sys.argv) > 6 else None
FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
NS = "{http://www.w3.org/2000/svg}"
recs = records(SESSION)
rate = rate_millihertz(recs)
tick_list = ticks(SESSION)
start = round(float(FROM_S) * 1000)
to = tick_list[-1].t_ms if TO_S == "last" else round(float(TO_S) * 1000)
end = min(to, tick_list[-1].t_ms)  # nothing is drawn past the last tick
root = ET.parse(SVG).getroot()
problems = []


def fail(message):
    sys.exit(f"{SVG}: {message}")


def attrs(element, *names):
    return [element.get(n) for n in names]


box = next(r for r in root.iter(NS + "rect") if r.get("fill") == "none")
left, top, width, height = (float(v) for v in attrs(box, "x", "y", "width", "height"))


def x_of(t_ms):
    t = min(max(t_ms, start), to)
    return left + width * (t - start) / (to - start)


def column(t_ms):
    return math.floor(x_of(t_ms) + 0.5)


def time_of(tick):
    return tick * 1_000_000 // rate


# --- The drive and pivot lines -------------------------------------------------

def segments(index):
    """(from, to, value or None: nothing sent) for each tick's frame, held
    until the next tick's, the last tick a point; clipped to the range."""
    out = []
    for i, t in enumerate(tick_list):
        value = t.data[index] if t.result == "sent" else None
        if i + 1 == len(tick_list):
            out.append((t.t_ms, t.t_ms, value))
        elif tick_list[i + 1].tick == t.tick + 1:
            out.append((t.t_ms, tick_list[i + 1].t_ms, value))
        else:  # ticks the loop did not run: nothing went out
            out.append((t.t_ms, time_of(t.tick + 1), value))
            out.append((time_of(t.tick + 1), tick_list[i + 1].t_ms, None))
    clipped = []
    for a, b, v in out:
        if (b > start or a == b >= start) and a <= end:
            clipped.append((max(a, start), min(b, end), v))
    return clipped


def stretches(segs):
    """The runs of frames sent, each a list of segments."""
    runs, current = [], []
    for s in segs:
        if s[2] is None:
            runs += [current] if current else []
            current = []
        else:
            current.append(s)
    return runs + ([current] if current else [])


def collapse(values):
    return [v for i, v in enumerate(values) if i == 0 or values[i - 1] != v]


def is_subsequence(part, whole):
    it = iter(whole)
    return all(any(v == w for w in it) for v in part)


def drawn_lines(d):
    lines = []
    for part in re.findall(r"M[^M]*", d):
        points = [p.split() for p in part[1:].split("L")]
        lines.append([(int(x), round((top + height - float(y)) * 255 / height)) for x, y in points])
    return lines


def check_line(name, d, index):
    want = stretches(segments(index))
    got = drawn_lines(d)
    if len(got) != len(want):
        fail(f"{name}: {len(got)} lines drawn, the frames sent make {len(want)} (a break where a tick sent nothing)")
    for n, (stretch, points) in enumerate(zip(want, got)):
        held = {}  # column: the values that held in it, in time order
        for a, b, v in stretch:
            for c in range(column(a), column(b) + 1):
                held.setdefault(c, []).append(v)
        held = {c: collapse(vs) for c, vs in held.items()}
        first, last = (column(stretch[0][0]), stretch[0][2]), (column(stretch[-1][1]), stretch[-1][2])
        if points[0] != first or points[-1] != last:
            fail(f"{name} line {n}: drawn from {points[0]} to {points[-1]} (column, value), "
                 f"the frames from {first} to {last}")
        at_column = {}
        for i, (c, v) in enumerate(points):
            if i and c < points[i - 1][0]:
                fail(f"{name} line {n}: point {i} at column {c} after column {points[i - 1][0]}: not in time order")
            if c not in held:
                fail(f"{name} line {n}: a point at column {c}, where no frame held")
            at_column.setdefault(c, []).append(v)
            if i and c > points[i - 1][0]:
                was = points[i - 1][1]
                if v != was:
                    fail(f"{name} line {n}: a slope from {points[i - 1]} to {(c, v)}: no frame between had those values")
                for between in range(points[i - 1][0] + 1, c):
                    if held.get(between) != [v]:
                        fail(f"{name} line {n}: level at {v} across column {between}, where {held.get(between)} held")
        for c, values in at_column.items():
            drawn = collapse(values)
            if not is_subsequence(drawn, held[c]):
                fail(f"{name} line {n}: column {c} drawn {drawn}, the frames held {held[c]} (in that order)")
            if min(held[c]) not in drawn or max(held[c]) not in drawn:
                fail(f"{name} line {n}: column {c} drawn {drawn}, its lowest or highest of {held[c]} missing")


catalogue = [json.loads(l) for l in subprocess.check_output([BIN, "frame", "signals", "--json"]).splitlines()]
byte = {s["name"]: s["byte"] for s in catalogue}
paths = [p.get("d") for p in root.iter(NS + "path")]
if len(paths) != 2:
    fail(f"{len(paths)} paths, expected drive's and pivot's")
for name, d in zip(("drive", "pivot"), paths):
    check_line(name, d, byte[name])

# --- The range's ticks ------------------------------------------------------------

source_line = next((t.text for t in root.iter(NS + "text") if re.search(r" s, \d+ ticks$", t.text or "")), "")
in_range = sum(1 for t in tick_list if start <= t.t_ms <= to)
if not source_line.endswith(f" s, {in_range} ticks"):
    fail(f"the page says '{source_line}', the session ran {in_range} ticks from {start} to {to} ms")

# --- The state band and who reset --------------------------------------------

BAND_TOP, BAND_HEIGHT = 74.0, 20.0
STATE_NAMES = {"stopping": "shutting down", "suspended": "suspended (Ctrl-Z)"}
legend = {}
rects = list(root.iter(NS + "rect"))
texts = list(root.iter(NS + "text"))
for r in rects:
    if r.get("height") == "9.0" and r.get("width") == "10.00":
        label = next(t for t in texts if t.get("y") == f"{float(r.get('y')) + 8:.1f}"
                     and abs(float(t.get("x")) - float(r.get("x")) - 13) < 0.05)
        legend[r.get("fill")] = label.text


def band_names():
    """(time, what the band says from then on), from the state and stop records."""
    changes, state, whose = [], None, None
    for kind, text in recs:
        if kind not in ("state", "stop", "reset"):
            continue
        t, rest = text.split(" ", 1)
        if kind == "state":
            state = rest
        elif kind == "stop" and '"again":true' in rest:
            continue  # pressed again while stopped: whose the stop is did not change
        elif kind == "stop":
            whose = rest.split(" ")[0].strip('"')
            whose = "frame gate" if whose == "frame" else whose
        else:
            whose = None
        if state == "stopped":
            name = f"stopped by the {whose}" if whose else "stopped (whose: not recorded)"
        else:
            name = STATE_NAMES.get(state, state)
        if changes and changes[-1][0] == int(t):
            changes.pop()
        changes.append((int(t), name))
    return changes


changes = band_names()
want_bands = [(start, n) for t, n in changes if t <= start][-1:]
want_bands += [(t, n) for t, n in changes if start < t <= end]
want_bands = [b for i, b in enumerate(want_bands) if i == 0 or want_bands[i - 1][1] != b[1]]
bands = sorted((float(r.get("x")), float(r.get("x")) + float(r.get("width")), legend.get(r.get("fill"), r.get("fill")))
               for r in rects if r.get("y") == f"{BAND_TOP:.1f}" and r.get("height") == f"{BAND_HEIGHT:.1f}")
got_bands = [b for i, b in enumerate(bands) if i == 0 or bands[i - 1][2] != b[2]]
if [n for _, _, n in got_bands] != [n for _, n in want_bands]:
    fail(f"the state band says {[n for _, _, n in got_bands]}, the session {[n for _, n in want_bands]} "
         f"from {FROM_S} s")
for (x0, _, n), (t, _) in zip(got_bands, want_bands):
    if abs(x0 - x_of(t)) > 0.06:
        fail(f"the band '{n}' begins at x {x0}, it began at {t} ms (x {x_of(t):.2f})")
if not -0.06 <= bands[-1][1] - x_of(end) <= 0.6:  # a band is at least 0.6 px wide
    fail(f"the state band ends at x {bands[-1][1]}, the session's last tick in the range at x {x_of(end):.2f}")

resets = sorted(float(l.get("x1")) for l in root.iter(NS + "line") if l.get("stroke") == "#212121")
want_resets = [x_of(int(text.split(" ")[0])) for kind, text in recs
               if kind == "reset" and start <= int(text.split(" ")[0]) <= end]
if len(resets) != len(want_resets) or any(abs(a - b) > 0.06 for a, b in zip(resets, want_resets)):
    fail(f"reset ticks at x {resets}, the session's resets in the range at x {[round(x, 2) for x in want_resets]}")

# --- Labels: measured, none over another ---------------------------------------


def advances(path):
    """The advance width of each printable ASCII character, in em (the font's cmap format 4 and hmtx)."""
    data = open(path, "rb").read()
    tables = {}
    for i in range(struct.unpack(">H", data[4:6])[0]):
        tag, _, offset, _ = struct.unpack(">4sIII", data[12 + 16 * i:28 + 16 * i])
        tables[tag.decode()] = offset
    units = struct.unpack(">H", data[tables["head"] + 18:tables["head"] + 20])[0]
    metrics = struct.unpack(">H", data[tables["hhea"] + 34:tables["hhea"] + 36])[0]
    widths = [struct.unpack(">H", data[tables["hmtx"] + 4 * i:tables["hmtx"] + 4 * i + 2])[0] for i in range(metrics)]
    cmap = tables["cmap"]
    for i in range(struct.unpack(">H", data[cmap + 2:cmap + 4])[0]):
        platform, encoding, offset = struct.unpack(">HHI", data[cmap + 4 + 8 * i:cmap + 12 + 8 * i])
        if (platform, encoding) == (3, 1):
            sub = cmap + offset
    n2 = struct.unpack(">H", data[sub + 6:sub + 8])[0]
    ends = struct.unpack(f">{n2 // 2}H", data[sub + 14:sub + 14 + n2])
    starts = struct.unpack(f">{n2 // 2}H", data[sub + 16 + n2:sub + 16 + 2 * n2])
    deltas = struct.unpack(f">{n2 // 2}h", data[sub + 16 + 2 * n2:sub + 16 + 3 * n2])
    range_at = sub + 16 + 3 * n2
    range_offsets = struct.unpack(f">{n2 // 2}H", data[range_at:range_at + n2])
    out = {}
    for code in range(32, 127):
        k = next(k for k in range(n2 // 2) if ends[k] >= code)
        if range_offsets[k] == 0:
            glyph = (code + deltas[k]) & 0xFFFF
        else:
            at = range_at + 2 * k + range_offsets[k] + 2 * (code - starts[k])
            glyph = struct.unpack(">H", data[at:at + 2])[0]
            glyph = (glyph + deltas[k]) & 0xFFFF if glyph else 0
        out[chr(code)] = widths[min(glyph, metrics - 1)] / units
    return out


em = advances(FONT)


def extent(t):
    size = float(re.search(r"[\d.]+", t.get("font-size")).group())
    w = sum(em.get(c, 1.0) for c in t.text) * size
    x = float(t.get("x"))
    return (x - w, x) if t.get("text-anchor") == "end" else (x, x + w)


for row, name in ((BAND_TOP + 13, "the stop labels"), (BAND_TOP - 2, "the reset labels")):
    placed = sorted((extent(t), t.text) for t in texts if t.get("y") == f"{row:.1f}")
    for ((a0, a1), a), ((b0, b1), b) in zip(placed, placed[1:]):
        if b0 < a1:
            fail(f"{name}: '{a}' ({a0:.1f} to {a1:.1f}) and '{b}' ({b0:.1f} to {b1:.1f}) overlap")
    for (x0, x1), text in placed:
        if x0 < left or x1 > left + width:
            fail(f"{name}: '{text}' ({x0:.1f} to {x1:.1f}) runs off the band ({left} to {left + width})")
        if row == BAND_TOP + 13:
            band = next(((b0, b1, n) for b0, b1, n in bands if b0 <= x0 < b1), None)
            if band is None or x1 > band[1] or text not in (band[2], band[2].removeprefix("stopped by the ")):
                fail(f"the stop label '{text}' ({x0:.1f} to {x1:.1f}) is not within a band it names: {band}")

# --- Every stop press on its lane --------------------------------------------

if STOP_BUTTON:
    for who, prefix in (("operator", ""), ("supervisor", "supervisor ")):
        presses, down = [], None
        for kind, text in recs:
            m = re.fullmatch(rf"(\d+) +{prefix}button +{STOP_BUTTON} +([01])", text) if kind == "event" else None
            if m and m.group(2) == "1":
                down = int(m.group(1))
            elif m and down is not None:
                presses.append((down, int(m.group(1))))
                down = None
        presses = [(a, b) for a, b in presses if b >= start and a <= end]
        lane_label = next((t for t in texts if t.text == f"stop button ({who})"), None)
        if lane_label is None:
            if presses:
                fail(f"no lane 'stop button ({who})', and the session has {len(presses)} presses in the range")
            continue
        y = f"{float(lane_label.get('y')) - 8:.1f}"
        marks = sorted((float(r.get("x")), float(r.get("x")) + float(r.get("width")))
                       for r in rects if r.get("y") == y and r.get("height") == "9.0" and r.get("fill") != "#f4f4f4")
        if len(marks) != len(presses):
            fail(f"the {who}'s stop lane has {len(marks)} marks, the session {len(presses)} presses in the range")
        for (x0, x1), (a, b) in zip(marks, presses):
            if abs(x0 - x_of(a)) > 0.06 or x1 < x_of(b) - 0.06 or x1 - x0 < 2 - 0.01:
                fail(f"the {who}'s stop pressed {a} to {b} ms: marked from x {x0} to {x1}, "
                     f"pressed from x {x_of(a):.2f} to {x_of(b):.2f} (a mark at least 2 px wide)")

print("the plot draws the session's frames, states, resets, stop presses and labels as recorded")
