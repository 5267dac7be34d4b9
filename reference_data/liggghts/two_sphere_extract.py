#!/usr/bin/env python3
"""Reduce one LIGGGHTS two-sphere dump to the quantities tamp's case compares.

usage: two_sphere_extract.py DUMP MODEL E NU RHO R V0 GAP0 E_IN CHARVEL DT [--header]

Prints one CSV row (or the header). Definitions, the same as tamp's
src/verify/cases/probe.rs (binary_collision):
- overlap of step n: 2R - (x2 - x1), from the dumped positions (%.17g);
- restitution: -(vx2 - vx1)_last / (vx2 - vx1)_first, full-step velocities, the
  last dumped step being long after separation;
- contact_duration: from the first to the last sign change of the overlap, each
  crossing interpolated linearly between the two samples around it, times dt;
- max_overlap: the largest sampled overlap (no refinement).
Plain Python, no packages.
"""
import sys

COLUMNS = ["model", "restitution_in", "time_step", "youngs_modulus", "poisson_ratio",
           "density", "radius", "relative_speed", "initial_gap", "characteristic_velocity",
           "steps_in_contact", "restitution", "contact_duration", "max_overlap"]


def read_dump(path):
    """Per step: (x1, vx1, x2, vx2) from a `dump custom ... id x vx`."""
    out = []
    with open(path) as f:
        lines = f.read().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            n = int(lines[i + 3])
            rows = {}
            for k in range(n):
                vals = lines[i + 9 + k].split()
                rows[int(vals[0])] = (float(vals[1]), float(vals[2]))
            out.append(rows[1] + rows[2])
            i += 9 + n
        else:
            i += 1
    return out


def main():
    if "--header" in sys.argv:
        print(",".join(COLUMNS))
        return
    path, model = sys.argv[1], sys.argv[2]
    E, nu, rho, R, v0, gap0, e_in, charvel, dt = map(float, sys.argv[3:12])
    steps = read_dump(path)
    ov = [2 * R - (x2 - x1) for (x1, _, x2, _) in steps]
    vrel = [vx2 - vx1 for (_, vx1, _, vx2) in steps]
    inside = [n for n, d in enumerate(ov) if d > 0]
    first, last = inside[0], inside[-1]
    if last + 1 >= len(ov) or inside != list(range(first, last + 1)):
        sys.exit(f"{path}: the contact is not one closed interval inside the run")
    t_in = (first - 1) + ov[first - 1] / (ov[first - 1] - ov[first])
    t_out = last + ov[last] / (ov[last] - ov[last + 1])
    row = [model, repr(e_in), repr(dt), repr(E), repr(nu), repr(rho), repr(R),
           repr(2 * v0), repr(gap0), repr(charvel), str(len(inside)),
           "%.17g" % (-vrel[-1] / vrel[0]), "%.17g" % ((t_out - t_in) * dt),
           "%.17g" % max(ov)]
    print(",".join(row))


if __name__ == "__main__":
    main()
