"""results.csv rows from a LAMMPS log of in.pair, in.wall or in.triplet: one row per
thermo line, labelled by the run.

usage: rows.py LOG LABEL   (appends to standard output, without a header)
"""
import sys

log, label = sys.argv[1], sys.argv[2]
inside = False
with open(log) as f:
    for line in f:
        words = line.split()
        if words[:2] == ["Step", "v_gap"]:
            inside = True
            continue
        if inside:
            if words and words[0] == "Loop":
                break
            print(",".join([label] + words))
