#!/usr/bin/env python3
"""The chute of LAMMPS's granular benchmark (`bench/in.chute`), rebuilt for tamp and LAMMPS.

LAMMPS's benchmark reads `data.chute`: 32 000 spheres (diameter 1, density 1, LJ units) in
a 40 x 20 box periodic in x and y, 912 of them (type 2) a frozen rough base at the bottom,
the other 31 088 flowing down a 26 degree slope in steady chute flow (a bed about 37
diameters deep). That file belongs to LAMMPS, so this script makes an equivalent one:

  deposit OUT.scene.json
      a tamp scene that only places 32 000 spheres by ballistic deposition onto z = 0
      across the periodic 40 x 20 footprint (0 steps; its trajectory.csv is the bed).
  warmup TRAJ.csv OUT.scene.json --steps W
      the 912 lowest spheres become the frozen base (prescribed velocity 0), the rest get a
      Bagnold chute profile plus random fluctuations; tamp then runs W steps of the
      benchmark's physics so that the contacts and the flow settle into each other.
  bench SOURCE OUT_DIR --steps N
      from a warm-up trajectory (SOURCE.csv, with the warm-up scene beside it as
      --scene) or from a LAMMPS data file such as a local copy of LAMMPS's own
      data.chute (SOURCE is then `--data FILE`), writes the timed start state twice:
      OUT_DIR/chute.scene.json for tamp and OUT_DIR/lammps/{data.chute,in.chute} for
      LAMMPS, with the same particles in the same order and the same settings.
  measure (--tamp TRAJ.csv --scene SCENE | --lammps DUMP)
      the same sanity numbers for either code's final state.

The LAMMPS deck is ours, written to match bench/in.chute line for line; nothing of
LAMMPS's is copied here. Units: LAMMPS's LJ numbers are used as SI numbers in tamp
(sigma = 1 m, m = 1 kg, tau = 1 s).
"""

import argparse
import json
import math
import os
import sys

import numpy as np

BOX = (40.0, 20.0)  # periodic x, y (diameters)
N_TOTAL = 32000
N_BASE = 912
DIAMETER = 1.0
DENSITY = 1.0  # LAMMPS atom_style sphere: mass = density * pi/6 * d^3
MASS = DENSITY * math.pi / 6.0 * DIAMETER**3
ANGLE = 26.0  # fix gravity 1.0 chute 26.0
KN = 200000.0  # pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
GAMMA_N = 50.0  # LAMMPS damps with meff * gamma_n
FRICTION = 0.5
DT = 1e-4
SKIN = 0.1  # neighbor 0.1 bin
# Bagnold profile of the warm-up start, u(z) = U (1 - (1 - z/H)^1.5) above the base:
# U is the surface speed of a steady 26 degree chute of this depth (LAMMPS's data.chute
# has 14.5 at the top), the fluctuations about 0.3 in every component as in that flow.
SURFACE_SPEED = 14.5
FLUCTUATION = 0.3


def gravity():
    a = math.radians(ANGLE)
    # LAMMPS's `chute` style tilts gravity from -z towards +x.
    return [math.sin(a), 0.0, -math.cos(a)]


def cell_order(pos):
    """Particle order by 1.1-diameter cells (z, then y, then x), as LAMMPS's atom sort
    orders its bins, so neither code starts from a scattered memory layout."""
    edge = DIAMETER + SKIN
    c = np.floor((pos - pos.min(axis=0)) / edge).astype(np.int64)
    return np.lexsort((c[:, 0], c[:, 1], c[:, 2]))


def read_trajectory(path, step=None):
    """Last frame (or frame `step`) of a tamp trajectory.csv: positions, velocities, spins
    in id order."""
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    last = data[:, 0].max() if step is None else step
    frame = data[data[:, 0] == last]
    frame = frame[np.argsort(frame[:, 1])]
    return frame[:, 3:6], frame[:, 6:9], frame[:, 9:12], frame[:, 2]


def base_mask_of(scene_path):
    with open(scene_path) as f:
        scene = json.load(f)
    return np.array(["prescribed_velocity" in p for p in scene["particles"]])


def wrap(pos):
    for k, length in enumerate(BOX):
        pos[:, k] = np.mod(pos[:, k], length)
        # np.mod can round up to the period itself; tamp wants [lo, hi).
        pos[pos[:, k] >= length, k] = 0.0
    return pos


def tamp_scene(name, pos, vel, omega, base, steps, out_every, overlap_tolerance):
    particles = []
    for x, v, w, b in zip(pos.tolist(), vel.tolist(), omega.tolist(), base.tolist()):
        p = {"position": x, "radius": DIAMETER / 2, "material": "lj"}
        if b:
            p["prescribed_velocity"] = [0.0, 0.0, 0.0]
        else:
            p["velocity"] = v
            p["omega"] = w
        particles.append(p)
    return {
        "name": name,
        # tamp's m = rho 4/3 pi R^3 and LAMMPS's m = density pi/6 d^3 agree at d = 2R.
        "materials": [{"name": "lj", "density": DENSITY}],
        # pair_style gran/hooke/history's physics term for term: the normal force
        # k_n delta - m* gamma_n v_n, with m* = m_i against a frozen sphere in both codes
        # (LAMMPS's freeze group, tamp's prescribed particle); its shear history (kt NULL
        # -> 2/7 kn; dampflag 0 -> no tangential dashpot) capped at mu |F_n|; the full
        # radii as lever arms in the contact velocity and the torques.
        "contact": {
            "normal": {"law": "linear", "stiffness": KN},
            "damping": {"kind": "mass_velocity", "eta_n0": GAMMA_N},
            "tangential": {
                "law": "lammps_linear_history",
                "stiffness": KN * 2 / 7,
                "x_gamma_t": 0.0,
                "history": "gran_hooke_history",
                "friction": FRICTION,
            },
            "lever_arm": "full_radius",
        },
        "particles": particles,
        "periodic": {"x": [0, BOX[0]], "y": [0, BOX[1]]},
        "gravity": gravity(),
        "rotation": {},
        "time_step": {"fixed": DT},
        "run": {"steps": steps},
        # skin = skin_fraction * smallest radius = 0.2 * 0.5 = LAMMPS's 0.1.
        "broad_phase": {"kind": "cells", "skin_fraction": SKIN / (DIAMETER / 2)},
        "stability": {"initial_overlap_tolerance": overlap_tolerance},
        "output": {
            "series_every": out_every,
            "series": ["kinetic_energy", "rotational_energy", "contact_count"],
            "trajectory_every": out_every,
        },
    }


def write_json(obj, path):
    with open(path, "w") as f:
        json.dump(obj, f, separators=(",", ":"))


def cmd_deposit(args):
    scene = {
        "name": "chute bed: 32000 spheres (d = 1) deposited on a 40 x 20 periodic footprint",
        "seed": args.seed,
        "materials": [{"name": "lj", "density": DENSITY}],
        "contact": {"normal": {"law": "linear", "stiffness": KN}},
        "deposit": [
            {
                "count": N_TOTAL,
                "radius": DIAMETER / 2,
                "material": "lj",
                "footprint": [[0, 0], list(BOX)],
                "floor": 0,
            }
        ],
        "periodic": {"x": [0, BOX[0]], "y": [0, BOX[1]]},
        "time_step": {"fixed": DT},
        "run": {"steps": 0},
        "output": {"series": ["contact_count"], "trajectory_every": 1},
    }
    write_json(scene, args.out)


def cmd_warmup(args):
    pos, _, _, _ = read_trajectory(args.trajectory, step=0)
    pos = pos.copy()
    pos[:, 2] -= DIAMETER / 2  # the base's lowest centres at z = 0, as in data.chute
    base = np.zeros(len(pos), dtype=bool)
    base[np.argsort(pos[:, 2], kind="stable")[:N_BASE]] = True
    z_base = pos[base, 2].max()
    height = pos[:, 2].max() - z_base
    rng = np.random.default_rng(args.seed)
    zeta = np.clip((pos[:, 2] - z_base) / height, 0.0, 1.0)
    vel = rng.normal(0.0, FLUCTUATION, size=pos.shape)
    vel[:, 0] += SURFACE_SPEED * (1.0 - (1.0 - zeta) ** 1.5)
    vel[base] = 0.0
    omega = np.zeros_like(pos)
    order = cell_order(pos)
    scene = tamp_scene(
        f"chute warm-up: {args.steps} steps from a deposited bed with a Bagnold profile",
        pos[order], vel[order], omega[order], base[order], args.steps, args.steps, 1e-6,
    )
    write_json(scene, args.out)


def read_lammps_data(path):
    """Atoms (atom_style sphere: id type diameter density x y z [image flags]) and
    Velocities (id vx vy vz wx wy wz) of a LAMMPS data file."""
    with open(path) as f:
        lines = f.read().split("\n")
    header = {}
    for line in lines[1:]:
        words = line.split()
        if line.strip() in ("Atoms", "Atoms # sphere"):
            break
        if len(words) >= 4 and words[2] + " " + words[3] in ("xlo xhi", "ylo yhi", "zlo zhi"):
            header[words[2]] = (float(words[0]), float(words[1]))
        if len(words) == 2 and words[1] == "atoms":
            n = int(words[0])

    def section(title):
        k = next(i for i, l in enumerate(lines) if l.strip().split(" #")[0] == title)
        rows = [l.split() for l in lines[k + 2 : k + 2 + n]]
        return np.array(rows, dtype=float)

    atoms = section("Atoms")
    atoms = atoms[np.argsort(atoms[:, 0])]
    vels = section("Velocities")
    vels = vels[np.argsort(vels[:, 0])]
    if not (np.all(atoms[:, 2] == DIAMETER) and np.all(atoms[:, 3] == DENSITY)):
        sys.exit(f"{path}: expected every diameter {DIAMETER} and density {DENSITY}")
    if header.get("xlo") != (0.0, BOX[0]) or header.get("ylo") != (0.0, BOX[1]):
        sys.exit(f"{path}: expected a 0 {BOX[0]} x 0 {BOX[1]} box, got {header}")
    return atoms[:, 4:7].copy(), vels[:, 1:4], vels[:, 4:7], atoms[:, 1] == 2


def write_lammps(out, pos, vel, omega, base, steps):
    os.makedirs(out, exist_ok=True)
    zlo = float(min(0.0, pos[:, 2].min() - DIAMETER / 2))
    zhi = float(pos[:, 2].max() + DIAMETER / 2)
    with open(os.path.join(out, "data.chute"), "w") as f:
        f.write("chute bed written by tamp's benches/peer/chute_bed.py\n\n")
        f.write(f"{len(pos)} atoms\n2 atom types\n\n")
        f.write(f"0 {BOX[0]} xlo xhi\n0 {BOX[1]} ylo yhi\n{zlo!r} {zhi!r} zlo zhi\n\n")
        f.write("Atoms # sphere\n\n")
        for i, (x, b) in enumerate(zip(pos.tolist(), base.tolist())):
            f.write(f"{i + 1} {2 if b else 1} {DIAMETER} {DENSITY} {x[0]!r} {x[1]!r} {x[2]!r}\n")
        f.write("\nVelocities\n\n")
        for i, (v, w) in enumerate(zip(vel.tolist(), omega.tolist())):
            f.write(f"{i + 1} {v[0]!r} {v[1]!r} {v[2]!r} {w[0]!r} {w[1]!r} {w[2]!r}\n")
    # The physics and the neighbour settings of bench/in.chute; only the output differs
    # (the sanity numbers, and a dump of the final state after the timed loop).
    deck = f"""# LAMMPS's bench/in.chute setup on the bed of benches/peer/chute_bed.py
units           lj
atom_style      sphere
boundary        p p fs
newton          off
comm_modify     vel yes

read_data       data.chute

pair_style      gran/hooke/history {KN} NULL {GAMMA_N} NULL {FRICTION} 0
pair_coeff      * *

neighbor        {SKIN} bin
neigh_modify    every 1 delay 0

timestep        {DT}

group           bottom type 2
group           active subtract all bottom
neigh_modify    exclude group bottom bottom

fix             1 all gravity 1.0 chute {ANGLE}
fix             2 bottom freeze
fix             3 active nve/sphere

compute         1 all erotate/sphere
compute         2 all ke
thermo_style    custom step atoms c_2 c_1
thermo_modify   norm no
thermo          {steps}

run             {steps}

write_dump      all custom final.dump id type x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
"""
    with open(os.path.join(out, "in.chute"), "w") as f:
        f.write(deck)


def cmd_bench(args):
    if args.data:
        pos, vel, omega, base = read_lammps_data(args.data)
        pos = wrap(pos)
        # LAMMPS's own bed has its frozen base spheres overlapping each other by up to
        # 0.8 % of a radius (LAMMPS never computes base-base pairs), flowing contacts
        # by more.
        tolerance = 0.05
        name = f"chute benchmark from {os.path.basename(args.data)}"
    else:
        pos, vel, omega, _ = read_trajectory(args.trajectory)
        base = base_mask_of(args.scene)
        pos = wrap(pos.copy())
        # Contacts under the weight of the bed overlap by ~1e-4 of a radius.
        tolerance = 0.05
        name = "chute benchmark: warmed-up bed of benches/peer/chute_bed.py"
    order = cell_order(pos)
    pos, vel, omega, base = pos[order], vel[order], omega[order], base[order]
    vel[base] = 0.0
    omega[base] = 0.0
    if args.perturb:
        # Another start of the same flow: every flowing velocity scaled by 1 + 1e-12 of a
        # normal deviate, which chaos grows into another trajectory of the same statistics.
        rng = np.random.default_rng(args.perturb)
        vel[~base] *= 1.0 + 1e-12 * rng.normal(size=(int((~base).sum()), 1))
        name += f", start perturbed (seed {args.perturb})"
    os.makedirs(args.out, exist_ok=True)
    name += f", {args.steps} steps of {DT}"
    write_json(
        tamp_scene(name, pos, vel, omega, base, args.steps, args.steps, tolerance),
        os.path.join(args.out, "chute.scene.json"),
    )
    write_lammps(os.path.join(args.out, "lammps"), pos, vel, omega, base, args.steps)
    print(f"{len(pos)} particles ({int(base.sum())} frozen), {args.steps} steps")


def contacts(pos, base):
    """Touching pairs (centre distance < d) through the periodic x, y images, counted by
    a cell grid: (free-free + free-base, base-base)."""
    edge = DIAMETER
    nx, ny = int(BOX[0] // edge), int(BOX[1] // edge)
    z0 = pos[:, 2].min()
    nz = int((pos[:, 2].max() - z0) // edge) + 3  # a spare empty layer stops the z roll
    c = np.stack(
        [
            np.minimum((pos[:, 0] / (BOX[0] / nx)).astype(int), nx - 1),
            np.minimum((pos[:, 1] / (BOX[1] / ny)).astype(int), ny - 1),
            ((pos[:, 2] - z0) // edge).astype(int),
        ],
        axis=1,
    )
    flat = (c[:, 0] * ny + c[:, 1]) * nz + c[:, 2]
    order = np.argsort(flat, kind="stable")
    counts = np.bincount(flat, minlength=nx * ny * nz)
    slots = counts.max()
    table = -np.ones((nx * ny * nz, slots), dtype=np.int64)
    first = np.concatenate([[0], np.cumsum(counts)[:-1]])
    rank = np.arange(len(pos)) - first[flat[order]]
    table[flat[order], rank] = order
    table = table.reshape(nx, ny, nz, slots)
    offsets = [(a, b, k) for a in (-1, 0, 1) for b in (-1, 0, 1) for k in (-1, 0, 1)]
    offsets = [o for o in offsets if o > (0, 0, 0)]  # half of them, and the cell itself
    free_pairs = base_pairs = 0

    def count(i, j):
        nonlocal free_pairs, base_pairs
        ok = (i >= 0) & (j >= 0)
        i, j = i[ok], j[ok]
        d = pos[i] - pos[j]
        d[:, :2] -= np.array(BOX) * np.round(d[:, :2] / np.array(BOX))
        touch = (d**2).sum(axis=1) < DIAMETER**2
        both = base[i] & base[j]
        free_pairs += int((touch & ~both).sum())
        base_pairs += int((touch & both).sum())

    for a in range(slots):
        for b in range(a + 1, slots):
            count(table[..., a].ravel(), table[..., b].ravel())
    for o in offsets:
        other = np.roll(table, shift=(-o[0], -o[1], -o[2]), axis=(0, 1, 2))
        for a in range(slots):
            for b in range(slots):
                count(table[..., a].ravel(), other[..., b].ravel())
    return free_pairs, base_pairs


def cmd_measure(args):
    if args.lammps:
        rows = np.loadtxt(args.lammps, skiprows=9)
        rows = rows[np.argsort(rows[:, 0])]
        base = rows[:, 1] == 2
        pos, vel, omega = rows[:, 2:5], rows[:, 5:8], rows[:, 8:11]
    else:
        pos, vel, omega, _ = read_trajectory(args.tamp)
        base = base_mask_of(args.scene)
    pos = wrap(pos.copy())
    inertia = 0.4 * MASS * (DIAMETER / 2) ** 2
    free, among_base = contacts(pos, base)
    out = {
        "kinetic_energy": 0.5 * MASS * float((vel**2).sum()),
        "rotational_energy": 0.5 * inertia * float((omega**2).sum()),
        "mean_vx_flowing": float(vel[~base, 0].mean()),
        "contacts": free,
        "contacts_within_base": among_base,
    }
    json.dump(out, sys.stdout)
    print()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("deposit")
    p.add_argument("out")
    p.add_argument("--seed", type=int, default=1)
    p.set_defaults(run=cmd_deposit)
    p = sub.add_parser("warmup")
    p.add_argument("trajectory")
    p.add_argument("out")
    p.add_argument("--steps", type=int, required=True)
    p.add_argument("--seed", type=int, default=1)
    p.set_defaults(run=cmd_warmup)
    p = sub.add_parser("bench")
    src = p.add_mutually_exclusive_group(required=True)
    src.add_argument("--trajectory", help="trajectory.csv of the warm-up run")
    src.add_argument("--data", help="a LAMMPS data file such as LAMMPS's bench/data.chute")
    p.add_argument("--scene", help="the warm-up scene (which particles are frozen)")
    p.add_argument("out")
    p.add_argument("--steps", type=int, required=True)
    p.add_argument("--perturb", type=int, default=0, help="seed of a 1e-12 perturbation of the flowing velocities (0: none)")
    p.set_defaults(run=cmd_bench)
    p = sub.add_parser("measure")
    src = p.add_mutually_exclusive_group(required=True)
    src.add_argument("--tamp", help="trajectory.csv of a tamp run")
    src.add_argument("--lammps", help="write_dump file of a LAMMPS run")
    p.add_argument("--scene", help="the tamp scene (which particles are frozen)")
    p.set_defaults(run=cmd_measure)
    args = ap.parse_args()
    if args.cmd == "bench" and args.trajectory and not args.scene:
        ap.error("bench --trajectory needs --scene (the warm-up scene)")
    if args.cmd == "measure" and args.tamp and not args.scene:
        ap.error("measure --tamp needs --scene")
    args.run(args)


if __name__ == "__main__":
    main()
