#!/usr/bin/env python3
"""results.csv rows of a replayed press cycle (lammps_die_press_cycle's
regenerate.sh): one per thermo line of the deck, every K steps. The deck prints
step, the punch's displacement dz and the floor's rise fz, the particles' push on
the punch (up), on the floor (down) and its mean over the K steps before the line,
their axial force on the die, the die's outward radial load, <rho^2> and the top of
the highest particle. usage: rows.py DIR SEED LOGFILE"""
import json, sys

d, seed, log = sys.argv[1], sys.argv[2], sys.argv[3]
h0 = json.load(open(f"{d}/cycle.json"))["cycle"]["press"]["h0"]
head = False
for line in open(f"{d}/{log}"):
    w = line.split()
    if w[:2] == ["Step", "v_dz"]:
        head = True
        continue
    if head and len(w) == 10 and w[0].isdigit():
        step, dz, fz, fp, ff, fmean, fdie, frad, spread, top = w
        print(f"{seed},{step},{h0 + float(dz)!r},{fz},{fp},{ff},{fmean},{fdie},{frad},{spread},{top}")
    else:
        head = False
