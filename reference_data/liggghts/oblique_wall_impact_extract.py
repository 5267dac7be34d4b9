#!/usr/bin/env python3
"""Reduce one LIGGGHTS oblique wall-impact dump to the rebound tamp's case compares.

usage: oblique_wall_impact_extract.py DUMP ANGLE E NU RHO R VT0 VN0 GAP0 E_IN MU DT
       oblique_wall_impact_extract.py --header

Prints one CSV row (or the header): the inputs (the incidence angle from the wall
normal in degrees, and the incident tangential and normal speeds exactly as passed to
LIGGGHTS), then from the last dumped step (%.17g) the rebound tangential velocity vx,
the rebound normal velocity vz (> 0: away from the wall) and the spin omega_y of the
sphere, which started at z = R + gap0 with velocity (vt0, 0, -vn0) above the plane
z = 0. The gap z - R at that step must be positive (the contact is over), else the
script stops. `final_gap` is printed for people and is not read by tamp.
Plain Python, no packages.
"""
import sys

COLUMNS = ["angle_deg", "tangential_speed", "normal_speed", "restitution_in", "friction",
           "time_step", "steps", "youngs_modulus", "poisson_ratio", "density", "radius",
           "initial_gap", "final_gap", "vx", "vz", "omega_y"]


def last_step(path):
    """(step, [x, y, z, vx, vy, vz, wx, wy, wz] of atom 1) of the last dumped block."""
    with open(path) as f:
        lines = f.read().split("\n")
    step, atom = None, None
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            for k in range(n):
                vals = lines[i + 9 + k].split()
                if int(vals[0]) == 1:
                    atom = [float(v) for v in vals[1:10]]
            i += 9 + n
        else:
            i += 1
    return step, atom


def main():
    if "--header" in sys.argv:
        print(",".join(COLUMNS))
        return
    path, angle = sys.argv[1], sys.argv[2]
    E, nu, rho, R, vt0, vn0, gap0, e_in, mu, dt = map(float, sys.argv[3:13])
    step, a = last_step(path)
    gap = a[2] - R
    if gap <= 0:
        sys.exit(f"{path}: the sphere still touches the wall at the last step ({gap:e} m)")
    row = [angle, "%.17g" % vt0, "%.17g" % vn0, repr(e_in), repr(mu), repr(dt), str(step),
           repr(E), repr(nu), repr(rho), repr(R), repr(gap0), "%.17g" % gap,
           "%.17g" % a[3], "%.17g" % a[5], "%.17g" % a[7]]
    print(",".join(row))


if __name__ == "__main__":
    main()
