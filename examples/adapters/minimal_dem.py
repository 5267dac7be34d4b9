#!/usr/bin/env python3
"""A minimal external engine for `tamp verify`, given as an example of an adapter.

This file shows tamp's engine contract end to end. It is NOT a second DEM engine, and its
results are NOT a reference for anything. It is a short, readable program that does every
part of the contract: it takes the arguments, reads the scene, writes the output file with
the right columns, and exits with the right code. Use it as a starting point when you wrap a
real engine (LIGGGHTS, LAMMPS, your own code) for tamp's verification suite.

The contract
------------
    minimal_dem.py SCENE_JSON OUT_DIR

SCENE_JSON is a *resolved* tamp scene (docs/scene-format.md). Every particle is listed in
`particles`, `time_step.fixed` is the step Δt and `run.steps` is the number of steps N.
OUT_DIR already exists. The adapter writes one file, OUT_DIR/trajectory.csv:

    step,id,radius,x,y,z,vx,vy,vz,omegax,omegay,omegaz[,fx,fy,fz,tx,ty,tz]

The force columns are there only when `output.forces` is true. They hold each particle's
total force and torque after that step. There is one row per particle (id = index in
`particles` + 1) at steps 0, k, 2k, ... (k = `output.trajectory_every`), at every step from
`output.trajectory_every_step_from` on when the scene sets it, and always one at the last
step N, never twice. Numbers are written with Python's repr(float), the shortest
form that reads back to the same double.

Exit codes:
    0  success; trajectory.csv is written.
    1  I/O error (the scene cannot be read or the output cannot be written).
    2  bad input: the scene is not what this program can read (malformed JSON, a wrong
       type, a missing material property, two particles with the same centre).
    3  the run became unstable: a position or velocity became non-finite. The message
       names the particle and the step. The rows written before that step are kept.
    4  the scene uses a feature this adapter does not implement. One line on stderr
       names the JSON field and the reason, e.g.
       `walls: this example adapter has no walls`. `tamp verify` then reports the
       case as not expressible on this engine, which is not an error.

What it implements
------------------
- Free spheres that do not rotate. The mass is m = ρ·4/3·πR³.
- Normal laws `hertz`, F = 4/3 E* √R* δ^{3/2}, and `linear`, F = k δ, where
  δ = R_i + R_j − |x_i − x_j| (contact when δ > 0). The force pushes i along
  n = (x_i − x_j)/|x_i − x_j| and j the other way.
- No damping, or `contact.damping` of kind `constant`: F_d = γ_n dδ/dt = −γ_n (v_i − v_j)·n.
  It is not clipped, so at the end of a contact the total normal force may pull, as in tamp,
  unless `contact.damping.limit` is true: then the total normal force is clamped at zero.
- Velocity Verlet, as in tamp's core/src/integrate.rs. All pairs are tested every step
  (brute force), which is fine for a few spheres.

What it refuses with exit 4
---------------------------
`walls`, `insert` and `deposit` when they are not empty; `gravity`, `rotation` (even `{}`),
`periodic`, `growth` and `die_compaction` when they are not null; a particle with
`prescribed_velocity` or a non-zero `omega`; `contact.tangential` and `contact.cohesion`;
every normal law other than `hertz` and `linear`; every damping kind other than `constant`;
`run.until`; a null `run.steps` or `time_step.fixed`; and any field it does not know, at the
top level, in `contact` or in a particle. A real adapter should refuse the same way. If it
ignored a feature silently, it would produce plausible numbers for a different scene.

It ignores `name`, `seed`, `resolved_from`, `broad_phase` (every tamp broad phase finds the
same pairs as brute force) and `stability`. So it applies none of tamp's own stability
checks except the one for non-finite values. Of `output` it reads only `trajectory_every`,
`trajectory_every_step_from` and `forces`: series, VTK frames, contact files and checkpoints are tamp's outputs, and the
contract does not ask an engine for them.

How to run it
-------------
The file starts with a `#!/usr/bin/env python3` line. Make it executable once
(`chmod +x examples/adapters/minimal_dem.py`), then run it from the repository root:

    tamp verify --engine command:examples/adapters/minimal_dem.py --case hertz_collision_time

It needs Python 3 and its standard library only. By hand, with a resolved scene:

    examples/adapters/minimal_dem.py scene.json out/ ; echo "exit $?"
"""

import json
import math
import os
import sys

EXIT_IO = 1
EXIT_BAD_INPUT = 2
EXIT_UNSTABLE = 3
EXIT_UNSUPPORTED = 4

HEADER = "step,id,radius,x,y,z,vx,vy,vz,omegax,omegay,omegaz"
FORCE_COLUMNS = ",fx,fy,fz,tx,ty,tz"


class Unsupported(Exception):
    """A feature the scene uses and this adapter does not implement (exit 4)."""

    def __init__(self, field, reason):
        super().__init__(f"{field}: {reason}")


class BadScene(Exception):
    """Input this adapter cannot read at all (exit 2)."""

    def __init__(self, field, reason):
        super().__init__(f"{field}: {reason}")


class Unstable(Exception):
    """The run produced a non-finite value (exit 3)."""


# --- reading the scene ------------------------------------------------------------------


def is_off(value):
    """True for the spellings a resolved scene may use for an empty list."""
    return value is None or value == []


def number(value, field, positive=False, non_negative=False):
    # bool is a subclass of int in Python, and `true` is never a number in tamp's scenes.
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise BadScene(field, f"must be a number, got {json.dumps(value)}")
    x = float(value)
    if not math.isfinite(x):
        raise BadScene(field, f"must be finite, got {value}")
    if positive and not x > 0.0:
        raise BadScene(field, f"must be > 0, got {value}")
    if non_negative and x < 0.0:
        raise BadScene(field, f"must be >= 0, got {value}")
    return x


def integer(value, field):
    if isinstance(value, bool) or not isinstance(value, int) or value < 0:
        raise BadScene(field, f"must be a non-negative integer, got {json.dumps(value)}")
    return value


def vec3(value, field):
    if not isinstance(value, list) or len(value) != 3:
        raise BadScene(field, f"must be an array of three numbers, got {json.dumps(value)}")
    return [number(c, f"{field}[{k}]") for k, c in enumerate(value)]


def obj(value, field):
    if not isinstance(value, dict):
        raise BadScene(field, f"must be an object, got {json.dumps(value)}")
    return value


# Top-level fields that need nothing from this adapter (see the module docstring).
IGNORED_TOP = {"name", "seed", "resolved_from", "broad_phase", "stability"}
READ_TOP = {"materials", "contact", "particles", "time_step", "run", "output"}
# Lists that switch a feature on by being non-empty.
REFUSED_LISTS = {
    "walls": "this example adapter has no walls",
    "insert": "this example adapter has no random insertion; list the particles explicitly",
    "deposit": "this example adapter has no ballistic deposition",
}
# Objects that switch a feature on by being present, even when empty (`rotation: {}`).
REFUSED_OBJECTS = {
    "gravity": "this example adapter has no gravity",
    "rotation": "this example adapter does not rotate particles",
    "periodic": "this example adapter has no periodic boundaries",
    "growth": "this example adapter has no growth stage",
    "die_compaction": "this example adapter does not run process documents",
}


def check_top_level(scene):
    for key, value in scene.items():
        if key in IGNORED_TOP or key in READ_TOP:
            continue
        if key in REFUSED_LISTS:
            if not is_off(value):
                raise Unsupported(key, REFUSED_LISTS[key])
        elif key in REFUSED_OBJECTS:
            if value is not None:
                raise Unsupported(key, REFUSED_OBJECTS[key])
        elif value is not None:
            # A field from a newer tamp: running without it would simulate another scene.
            raise Unsupported(key, "is not a field this example adapter knows")


def read_contact(contact):
    contact = obj(contact, "contact")
    for key, value in contact.items():
        if key in ("normal", "damping"):
            continue
        if key == "lever_arm":
            continue  # only matters with rotation and friction, both refused
        if key == "tangential":
            if value is not None:
                raise Unsupported("contact.tangential", "this example adapter has no friction")
        elif key == "cohesion":
            if value is not None:
                raise Unsupported("contact.cohesion", "this example adapter has no cohesion")
        elif value is not None:
            raise Unsupported(f"contact.{key}", "is not a field this example adapter knows")

    normal = obj(contact.get("normal"), "contact.normal")
    law = normal.get("law")
    if law == "hertz":
        normal_law = ("hertz", None)
    elif law == "linear":
        stiffness = number(normal.get("stiffness"), "contact.normal.stiffness", positive=True)
        normal_law = ("linear", stiffness)
    else:
        raise Unsupported(
            "contact.normal.law",
            f"this example adapter implements 'hertz' and 'linear', not {json.dumps(law)}",
        )

    damping = contact.get("damping")
    gamma_n, no_pull = 0.0, False
    if damping is not None:
        damping = obj(damping, "contact.damping")
        kind = damping.get("kind")
        if kind != "constant":
            raise Unsupported(
                "contact.damping.kind",
                f"this example adapter implements only 'constant', not {json.dumps(kind)}",
            )
        for key in damping:
            if key not in ("kind", "gamma_n", "limit"):
                raise Unsupported(f"contact.damping.{key}", "is not a field this example adapter knows")
        gamma_n = number(damping.get("gamma_n"), "contact.damping.gamma_n", non_negative=True)
        no_pull = damping.get("limit", False)
        if not isinstance(no_pull, bool):
            raise BadScene("contact.damping.limit", f"must be true or false, got {json.dumps(no_pull)}")
    return normal_law, gamma_n, no_pull


def read_materials(materials):
    if not isinstance(materials, list) or not materials:
        raise BadScene("materials", "must be a non-empty array")
    by_name = {}
    for k, m in enumerate(materials):
        m = obj(m, f"materials[{k}]")
        name = m.get("name")
        if not isinstance(name, str):
            raise BadScene(f"materials[{k}].name", "must be a string")
        # Properties are read lazily, per particle: a wall-only material (rigid, no
        # density) may sit in the list even though walls themselves are refused.
        by_name[name] = (k, m)
    return by_name


def material_property(materials, name, key, i, **rule):
    k, m = materials[name]
    if m.get("rigid"):
        raise BadScene(f"particles[{i}].material", f"'{name}' is rigid: only walls may use it")
    value = m.get(key)
    if value is None:
        raise BadScene(f"materials[{k}].{key}", f"is required by particles[{i}]")
    return number(value, f"materials[{k}].{key}", **rule)


PARTICLE_FIELDS = {"position", "radius", "material", "velocity", "omega", "prescribed_velocity"}


def read_particles(particles, materials, law):
    if not isinstance(particles, list) or not particles:
        raise BadScene("particles", "must list at least one particle (a resolved scene does)")
    out = []
    for i, p in enumerate(particles):
        path = f"particles[{i}]"
        p = obj(p, path)
        for key, value in p.items():
            if key not in PARTICLE_FIELDS and value is not None:
                raise Unsupported(f"{path}.{key}", "is not a field this example adapter knows")
        if p.get("prescribed_velocity") is not None:
            raise Unsupported(
                f"{path}.prescribed_velocity",
                "this example adapter integrates free particles only",
            )
        omega = p.get("omega")
        if omega is not None and any(c != 0.0 for c in vec3(omega, f"{path}.omega")):
            raise Unsupported(f"{path}.omega", "this example adapter does not rotate particles")
        position = vec3(p.get("position"), f"{path}.position")
        radius = number(p.get("radius"), f"{path}.radius", positive=True)
        velocity = p.get("velocity")
        velocity = [0.0, 0.0, 0.0] if velocity is None else vec3(velocity, f"{path}.velocity")
        name = p.get("material")
        if name not in materials:
            raise BadScene(f"{path}.material", f"names no material: {json.dumps(name)}")
        density = material_property(materials, name, "density", i, positive=True)
        mass = density * (4.0 / 3.0 * math.pi * radius * radius * radius)
        particle = {"x": position, "v": velocity, "r": radius, "m": mass}
        if law == "hertz":
            young = material_property(materials, name, "youngs_modulus", i, positive=True)
            poisson = material_property(materials, name, "poisson_ratio", i)
            particle["compliance"] = (1.0 - poisson * poisson) / young
        out.append(particle)
    return out


def read_scene(scene):
    scene = obj(scene, "scene")
    check_top_level(scene)
    normal_law, gamma_n, no_pull = read_contact(scene.get("contact"))
    materials = read_materials(scene.get("materials"))
    particles = read_particles(scene.get("particles"), materials, normal_law[0])

    time_step = obj(scene.get("time_step"), "time_step")
    if time_step.get("fixed") is None:
        # Estimating Δt is tamp's job; a resolved scene states the step it chose.
        raise Unsupported("time_step.fixed", "this example adapter needs a fixed time step")
    dt = number(time_step["fixed"], "time_step.fixed", positive=True)

    run = obj(scene.get("run"), "run")
    if run.get("until") is not None:
        raise Unsupported("run.until", "this example adapter runs a fixed number of steps")
    if run.get("steps") is None:
        raise Unsupported("run.steps", "this example adapter needs the number of steps")
    steps = integer(run["steps"], "run.steps")

    output = scene.get("output") or {}
    output = obj(output, "output")
    every = output.get("trajectory_every")
    every = 0 if every is None else integer(every, "output.trajectory_every")
    dense_from = output.get("trajectory_every_step_from")
    if dense_from is not None:
        dense_from = integer(dense_from, "output.trajectory_every_step_from")
    forces = output.get("forces")
    if forces is None:
        forces = False
    if not isinstance(forces, bool):
        raise BadScene("output.forces", f"must be true or false, got {json.dumps(forces)}")

    return {
        "law": normal_law,
        "gamma_n": gamma_n,
        "no_pull": no_pull,
        "particles": particles,
        "dt": dt,
        "steps": steps,
        "every": every,
        "dense_from": dense_from,
        "forces": forces,
    }


# --- the model ---------------------------------------------------------------------------


def build_pairs(particles, law):
    """Per-pair constants, computed once: the contact distance and the law's coefficient."""
    kind, stiffness = law
    pairs = []
    for i in range(len(particles)):
        for j in range(i + 1, len(particles)):
            pi, pj = particles[i], particles[j]
            reach = pi["r"] + pj["r"]
            if kind == "hertz":
                r_eff = pi["r"] * pj["r"] / reach
                e_eff = 1.0 / (pi["compliance"] + pj["compliance"])
                pairs.append((i, j, reach, r_eff, e_eff))
            else:
                pairs.append((i, j, reach, stiffness, None))
    return pairs


def compute_forces(x, v, pairs, hertz, gamma_n, no_pull, n):
    f = [[0.0, 0.0, 0.0] for _ in range(n)]
    for i, j, reach, a, b in pairs:
        xi, xj = x[i], x[j]
        dx, dy, dz = xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]
        d2 = dx * dx + dy * dy + dz * dz
        if d2 >= reach * reach:
            continue
        d = math.sqrt(d2)
        if d == 0.0:
            raise ZeroDivisionError((i, j))
        overlap = reach - d
        if overlap <= 0.0:
            continue
        nx, ny, nz = dx / d, dy / d, dz / d
        if hertz:
            # Same grouping as tamp's hertz_force, so the two agree to the last bits.
            fn = 4.0 / 3.0 * b * math.sqrt(a * overlap) * overlap
        else:
            fn = a * overlap
        if gamma_n:
            vi, vj = v[i], v[j]
            # dδ/dt > 0 while approaching, so the dashpot pushes then, and pulls while
            # the spheres separate; the sum is clamped at zero only when the scene says so.
            rate = -((vi[0] - vj[0]) * nx + (vi[1] - vj[1]) * ny + (vi[2] - vj[2]) * nz)
            fn += gamma_n * rate
            if no_pull and fn < 0.0:
                fn = 0.0
        fx, fy, fz = fn * nx, fn * ny, fn * nz
        fi, fj = f[i], f[j]
        fi[0] += fx
        fi[1] += fy
        fi[2] += fz
        fj[0] -= fx
        fj[1] -= fy
        fj[2] -= fz
    return f


def row(step, k, p, x, v, f):
    values = [p["r"], *x, *v, 0.0, 0.0, 0.0]
    if f is not None:
        values += [*f, 0.0, 0.0, 0.0]
    return f"{step},{k + 1}," + ",".join(repr(float(c)) for c in values)


def run(s, rows):
    particles = s["particles"]
    n = len(particles)
    dt, steps = s["dt"], s["steps"]
    half_dt = 0.5 * dt
    every = s["every"]
    dense_from = s["dense_from"]
    with_forces = s["forces"]
    hertz = s["law"][0] == "hertz"
    gamma_n = s["gamma_n"]
    no_pull = s["no_pull"]
    pairs = build_pairs(particles, s["law"])
    x = [list(p["x"]) for p in particles]
    v = [list(p["v"]) for p in particles]
    # half_dt/m once per particle, as tamp's kick multiplies F by (½Δt/m).
    kick = [half_dt / p["m"] for p in particles]

    def forces_at(step):
        try:
            return compute_forces(x, v, pairs, hertz, gamma_n, no_pull, n)
        except ZeroDivisionError as e:
            i, j = e.args[0]
            if step == 0:
                raise BadScene(
                    f"particles[{j}].position",
                    f"has the same centre as particles[{i}]: the contact normal is undefined",
                )
            raise Unstable(
                f"unstable at step {step} (t = {step * dt:e} s): contact {i + 1}-{j + 1}: "
                "the centres coincide"
            )

    def record(step, f):
        for k in range(n):
            rows.append(row(step, k, particles[k], x[k], v[k], f[k] if with_forces else None))

    f = forces_at(0)
    record(0, f)
    for step in range(1, steps + 1):
        for k in range(n):
            xk, vk, fk, h = x[k], v[k], f[k], kick[k]
            vk[0] += fk[0] * h
            vk[1] += fk[1] * h
            vk[2] += fk[2] * h
            xk[0] += vk[0] * dt
            xk[1] += vk[1] * dt
            xk[2] += vk[2] * dt
        # Evaluated with the half-step velocities, as tamp and LIGGGHTS do for damping.
        f = forces_at(step)
        for k in range(n):
            vk, fk, h = v[k], f[k], kick[k]
            vk[0] += fk[0] * h
            vk[1] += fk[1] * h
            vk[2] += fk[2] * h
            if not all(math.isfinite(c) for c in (*x[k], *vk)):
                raise Unstable(
                    f"unstable at step {step} (t = {step * dt:e} s): particle {k + 1} "
                    f"(particles[{k}]): its position or velocity is not finite"
                )
        # With trajectory_every = 0 only the first and last states are written.
        dense = dense_from is not None and step >= dense_from
        if step == steps or dense or (every > 0 and step % every == 0):
            record(step, f)


# --- the command -------------------------------------------------------------------------


def write_trajectory(out_dir, header, rows):
    path = os.path.join(out_dir, "trajectory.csv")
    with open(path, "w", encoding="utf-8", newline="\n") as fh:
        fh.write(header + "\n")
        for line in rows:
            fh.write(line + "\n")


def main(argv):
    if len(argv) != 3:
        print(f"usage: {os.path.basename(argv[0])} SCENE_JSON OUT_DIR", file=sys.stderr)
        return EXIT_BAD_INPUT
    scene_path, out_dir = argv[1], argv[2]
    try:
        with open(scene_path, encoding="utf-8") as fh:
            text = fh.read()
    except OSError as e:
        print(f"scene: cannot read {scene_path}: {e.strerror}", file=sys.stderr)
        return EXIT_IO
    try:
        scene = json.loads(text)
    except json.JSONDecodeError as e:
        print(f"scene: not valid JSON: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT

    rows = []
    code = 0
    try:
        s = read_scene(scene)
        header = HEADER + (FORCE_COLUMNS if s["forces"] else "")
        run(s, rows)
    except Unsupported as e:
        print(e, file=sys.stderr)
        return EXIT_UNSUPPORTED
    except BadScene as e:
        print(e, file=sys.stderr)
        return EXIT_BAD_INPUT
    except Unstable as e:
        # Keep the finite rows already recorded: they show how the run got there.
        print(e, file=sys.stderr)
        code = EXIT_UNSTABLE

    try:
        write_trajectory(out_dir, header, rows)
    except OSError as e:
        print(f"{out_dir}: cannot write trajectory.csv: {e.strerror}", file=sys.stderr)
        return EXIT_IO
    return code


if __name__ == "__main__":
    sys.exit(main(sys.argv))
