#!/usr/bin/env python3
"""Checks a capture decoded by `andros-bridge frame decode` (JSON lines on stdin).

  check_frames.py --bin BIN [--min N] [--enabled] [--neutral-tail N [--driving-before-tail]] [--code HEX] [--driving]

Fails (exit 1, saying why) unless: there are at least N frames, every frame is
valid, byte 11 is the code, at least one frame is enabled (--enabled) or
drives (--driving), and the last N frames are neutral (docs/mapping.md, the safety rules),
the frame before them driving (--driving-before-tail: the run was driving when it stopped).
"""
import argparse, json, subprocess, sys

ap = argparse.ArgumentParser()
ap.add_argument("--bin", required=True, help="andros-bridge, whose `frame signals` names the kinds")
ap.add_argument("--min", type=int, default=1)
ap.add_argument("--enabled", action="store_true")
ap.add_argument("--driving", action="store_true")
ap.add_argument("--neutral-tail", type=int, default=0)
ap.add_argument("--code")
ap.add_argument("--driving-before-tail", action="store_true", help="the last non-neutral frame, just before the tail, drives")
ap.add_argument("--all-neutral", action="store_true", help="every frame neutral (a link regained: a fresh press first)")
a = ap.parse_args()
# docs/mapping.md's safety rules: neutral = every motion, weapon and interlock bit 0, drive
# and pivot at centre. The kinds come from the signal table, not a copy of it.
catalogue = [json.loads(l) for l in subprocess.check_output([a.bin, "frame", "signals", "--json"]).splitlines()]
ZEROED = {s["name"] for s in catalogue if s["kind"] in ("motion", "weapon", "interlock")}


def neutral(s):
    return s["drive"] == 128 and s["pivot"] == 128 and all(s[k] == 0 for k in ZEROED)


frames = [json.loads(line) for line in sys.stdin if line.strip()]
problems = []
if len(frames) < a.min:
    problems.append(f"{len(frames)} frames, expected at least {a.min}")
bad = [f["offset"] for f in frames if not f["valid"]]
if bad:
    problems.append(f"invalid frames at offsets {bad[:5]}")
if a.code and any(f["signals"]["code"] != int(a.code, 16) for f in frames):
    problems.append(f"byte 11 is not 0x{a.code}: {sorted({f['signals']['code'] for f in frames})}")
if a.enabled and not any(f["signals"]["safety"] == 1 for f in frames):
    problems.append("no frame is enabled (safety = 1)")
if a.driving and not any(f["signals"]["drive"] != 128 for f in frames):
    problems.append("no frame drives")
if a.all_neutral and not all(neutral(f["signals"]) for f in frames):
    problems.append("a frame is not neutral: " + str([(f["offset"], f["signals"]["safety"], f["signals"]["drive"])
                                                     for f in frames if not neutral(f["signals"])][:5]))
tail = frames[-a.neutral_tail:] if a.neutral_tail else []
if a.neutral_tail and (len(tail) < a.neutral_tail or not all(neutral(f["signals"]) for f in tail)):
    problems.append(f"the last {a.neutral_tail} frames are not all neutral: "
                    + str([(f["signals"]["safety"], f["signals"]["drive"]) for f in frames[-6:]]))
if a.driving_before_tail:
    moving = [f for f in frames if not neutral(f["signals"])]
    if not moving or moving[-1]["signals"]["drive"] == 128:
        problems.append("no driving frame before the neutral tail: the run was not driving when it stopped")
for p in problems:
    print(p)
sys.exit(1 if problems else 0)
