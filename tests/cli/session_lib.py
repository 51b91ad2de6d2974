"""A flight recorder session (docs/recording.md, "What a session holds") as
the command-line tests read it: what a live run recorded is the anchor of a
check whose verdict must not depend on how busy the machine was (when a test
sent a signal, when its reads saw a frame).

  records(PATH)  every record: (kind, text after the kind, hash left off)
  ticks(PATH)    every tick that ran, rebuilt from the frame records (one per
                 change; the ticks between repeat the one before; gap=N: N
                 ticks skipped before it): Tick(tick, t_ms, result, data)
  Catalogue(BIN) what a frame's data bytes say (`frame signals --json`)
"""
import json, subprocess
from collections import namedtuple

Tick = namedtuple("Tick", "tick t_ms result data")  # result: sent, busy, down or none; data: the 16 bytes


def records(path):
    out = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            _, kind, rest = (line.rstrip("\n").rsplit(" ", 1)[0] + " ").split(" ", 2)
            out.append((kind, rest.strip()))
    return out


def rate_millihertz(recs):
    return next(json.loads(text)["rate_millihertz"] for kind, text in recs if kind == "settings")


def ticks(path):
    recs = records(path)
    rate = rate_millihertz(recs)
    frames = [text.split() for kind, text in recs if kind == "frame"]
    end = [text.split() for kind, text in recs if kind == "end"]
    last = int(end[0][2]) if end else int(frames[-1][0])
    out = []
    for i, (tick, t_ms, result, data, gap) in enumerate(frames):
        first = int(tick)
        if first * 1_000_000 // rate != int(t_ms):
            raise ValueError(f"{path}: tick {tick} at {t_ms} ms: not on the grid of {rate} mHz")
        through = int(frames[i + 1][0]) - int(frames[i + 1][4][len("gap="):]) - 1 if i + 1 < len(frames) else last
        for k in range(first, through + 1):
            out.append(Tick(k, k * 1_000_000 // rate, result, bytes.fromhex(data)))
    return out


class Catalogue:
    """The frame's signals (`frame signals --json`): which bytes and bits are drive, pivot and the zeroed ones."""

    def __init__(self, bin_):
        rows = [json.loads(l) for l in subprocess.check_output([bin_, "frame", "signals", "--json"]).splitlines()]
        self.byte = {r["name"]: r["byte"] for r in rows}
        self.zeroed = [(r["byte"], r.get("bit")) for r in rows if r["kind"] in ("motion", "weapon", "interlock")]

    def value(self, data, name):
        return data[self.byte[name]]

    def neutral(self, data):
        """Drive and pivot at centre, no motion, weapon or interlock signal on."""
        if data[self.byte["drive"]] != 128 or data[self.byte["pivot"]] != 128:
            return False
        return all((data[b] if bit is None else data[b] >> bit & 1) == 0 for b, bit in self.zeroed
                   if b not in (self.byte["drive"], self.byte["pivot"]))
