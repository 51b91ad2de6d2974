#!/usr/bin/env python3
"""export_without_model.py FILE csv|jsonl: an export's rows with the vehicle
model's columns left out (export gained them after session format 3; the
rest of an old session's export must read as it did: test_old_session.sh).
Fails if FILE has not every one of them."""
import csv, io, json, sys

MODEL = {"vehicle_x", "vehicle_y", "vehicle_heading", "front_flipper", "rear_flipper", "arm_torso", "arm_shoulder",
         "arm_elbow", "arm_wrist", "arm_wrist_extension", "gripper_opening", "gripper_rotation"}
path, fmt = sys.argv[1], sys.argv[2]
seen = set()
data = open(path, newline="").read()
out = io.StringIO(newline="")
if fmt == "csv":
    rows = list(csv.reader(io.StringIO(data, newline="")))
    keep = [i for i, name in enumerate(rows[0]) if name not in MODEL]
    seen = set(rows[0]) & MODEL
    w = csv.writer(out, lineterminator="\n")
    for r in rows:
        w.writerow([r[i] for i in keep])
else:
    for line in data.splitlines():
        obj = json.loads(line)
        seen |= obj.keys() & MODEL
        out.write(json.dumps({k: v for k, v in obj.items() if k not in MODEL}, separators=(",", ":"), ensure_ascii=False) + "\n")
sys.stdout.write(out.getvalue())
if seen != MODEL:
    sys.exit(f"{path}: the model's columns {sorted(MODEL - seen)} are missing")
