#!/usr/bin/env python3
"""One results.csv row per record of a replayed die pressing, LIGGGHTS or LAMMPS
(the die-compaction cases' regenerate.sh): the punch and floor pressures from the
deck's thermo output, the densities from `tamp import-liggghts-dump --die-stroke`'s
die.csv. usage: die_replay_rows.py DIR SEED LOGFILE"""
import json, math, sys


def thermo_forces(path):
    """{step: (time, F_punch, F_floor)} from a replay deck's thermo output.

    Thermo rows: step time F_punch F_floor and one more column (the particles' force
    on punch and floor along z, N); each run prints its first and last step. A run's
    first row repeats the previous run's last step (in LIGGGHTS 3.8 with the mesh
    forces counted twice: it adds the setup's force to the step's), so the first row
    of a step is kept: the end of the run."""
    forces, head = {}, False
    for line in open(path):
        w = line.split()
        if w[:2] == ["Step", "Time"]:
            head = True
            continue
        if head and w and w[0].isdigit() and len(w) == 5:
            forces.setdefault(int(w[0]), (float(w[1]), float(w[2]), float(w[3])))
        else:
            head = False
    return forces


def main(d, seed, log):
    s = json.load(open(f"{d}/stroke.json"))
    st, area = s["stroke"], math.pi * (0.5 * s["die_diameter"]) ** 2
    n = st["steps_per_record"]
    forces = thermo_forces(f"{d}/{log}")
    die = [l.strip().split(",") for l in open(f"{d}/measured/die.csv")][1:]
    heights = [st["h0"]] + st["heights"]
    pressures = [0.0] + st["pressures"]
    for k, row in enumerate(die):
        _, fp, ff = forces[k * n]
        print(f"{seed},{k},{k * st['interval']!r},{heights[k]!r},{st['h0']!r},{st['dt']!r},{n},{pressures[k]!r},"
              f"{fp / area!r},{-ff / area!r},{row[3]},{row[4]}")


if __name__ == "__main__":
    main(*sys.argv[1:4])
