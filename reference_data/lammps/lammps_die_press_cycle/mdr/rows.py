#!/usr/bin/env python3
"""results.csv of the mdr press cycle: one row per thermo line (the first of a step
that two runs both print). usage: rows.py LOG CYCLE_JSON"""
import json, sys

h0 = json.load(open(sys.argv[2]))["cycle"]["press"]["h0"]
print("step,punch_face,floor_rise,punch_force,floor_force,floor_force_mean")
seen, head = set(), False
for line in open(sys.argv[1]):
    w = line.split()
    if w[:2] == ["Step", "v_dz"]:
        head = True
        continue
    if head and len(w) == 6 and w[0].isdigit():
        if w[0] not in seen:
            seen.add(w[0])
            print(f"{w[0]},{h0 + float(w[1])!r},{w[2]},{w[3]},{w[4]},{w[5]}")
    else:
        head = False
