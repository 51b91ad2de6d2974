#!/usr/bin/env python3
"""Checks a capture decoded by `andros-bridge frame decode` (JSON lines on stdin).

  check_frames.py [--min N] [--enabled] [--neutral-tail N] [--code HEX] [--driving]

Fails (exit 1, saying why) unless: there are at least N frames, every frame is
valid, byte 11 is the code, at least one frame is enabled (--enabled) or
drives (--driving), and the last N frames are neutral (contract section 5).
"""
import argparse, json, sys

SELECTORS = {"speed_high", "speed_low", "inset_3", "inset_4", "inset_video_1", "inset_video_2",
             "main_video_2", "main_video_3", "main_video_4"}
BYTES = {"pivot", "drive", "arm_speed", "light", "code", "byte12", "battery"}


def neutral(s):
    if s["drive"] != 128 or s["pivot"] != 128:
        return False
    return all(v == 0 for k, v in s.items() if k not in SELECTORS and k not in BYTES)


ap = argparse.ArgumentParser()
ap.add_argument("--min", type=int, default=1)
ap.add_argument("--enabled", action="store_true")
ap.add_argument("--driving", action="store_true")
ap.add_argument("--neutral-tail", type=int, default=0)
ap.add_argument("--code")
a = ap.parse_args()
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
tail = frames[-a.neutral_tail:] if a.neutral_tail else []
if a.neutral_tail and (len(tail) < a.neutral_tail or not all(neutral(f["signals"]) for f in tail)):
    problems.append(f"the last {a.neutral_tail} frames are not all neutral: "
                    + str([(f["signals"]["safety"], f["signals"]["drive"]) for f in frames[-6:]]))
for p in problems:
    print(p)
sys.exit(1 if problems else 0)
