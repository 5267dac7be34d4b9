#!/usr/bin/env python3
"""Reduce one LIGGGHTS oblique two-sphere dump to the final state tamp's case compares.

usage: two_sphere_oblique_extract.py DUMP MODEL E NU RHO R V0 VT0 GAP0 E_IN MU CHARVEL DT
       two_sphere_oblique_extract.py --header

Prints one CSV row (or the header): the inputs, then from the last dumped step
(%.17g) the velocity (vx, vy) and spin omega_z of atom 1, which started at
-(R + gap0/2) on x with velocity (v0, vt0, 0); atom 2 is its mirror image. The
overlap 2R - |x2 - x1| at that step must be negative (the contact is over), else the
script stops. `final_overlap` is printed for people and is not read by tamp.
Plain Python, no packages.
"""
import math
import sys

COLUMNS = ["model", "restitution_in", "friction", "time_step", "steps", "youngs_modulus",
           "poisson_ratio", "density", "radius", "normal_speed", "tangential_speed",
           "initial_gap", "characteristic_velocity", "final_overlap", "vx", "vy", "omega_z"]


def last_step(path):
    """{id: [x, y, z, vx, vy, vz, wx, wy, wz]} and the step number of the last block."""
    with open(path) as f:
        lines = f.read().split("\n")
    step, atoms = None, None
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            atoms = {}
            for k in range(n):
                vals = lines[i + 9 + k].split()
                atoms[int(vals[0])] = [float(v) for v in vals[1:10]]
            i += 9 + n
        else:
            i += 1
    return step, atoms


def main():
    if "--header" in sys.argv:
        print(",".join(COLUMNS))
        return
    path, model = sys.argv[1], sys.argv[2]
    E, nu, rho, R, v0, vt0, gap0, e_in, mu, charvel, dt = map(float, sys.argv[3:14])
    step, atoms = last_step(path)
    a, b = atoms[1], atoms[2]
    overlap = 2 * R - math.sqrt(sum((b[k] - a[k]) ** 2 for k in range(3)))
    if overlap >= 0:
        sys.exit(f"{path}: the spheres still touch at the last step ({overlap:e} m)")
    row = [model, repr(e_in), repr(mu), repr(dt), str(step), repr(E), repr(nu), repr(rho),
           repr(R), repr(2 * v0), repr(2 * vt0), repr(gap0), repr(charvel),
           "%.17g" % overlap, "%.17g" % a[3], "%.17g" % a[4], "%.17g" % a[8]]
    print(",".join(row))


if __name__ == "__main__":
    main()
