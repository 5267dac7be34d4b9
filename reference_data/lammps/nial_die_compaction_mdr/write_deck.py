#!/usr/bin/env python3
"""Write the LAMMPS deck that presses a flattened NiAl specimen with the mdr normal
model (Zunker & Kamrin 2024; LAMMPS 22 Jul 2025 pair granular): NiAl's E and nu,
yield stress 800 MPa, no adhesion, psi_b 0.5, mdr damping (type 1) with
eta_n0 = 2 xi = 1.8 (tamp's critical_fraction xi = 0.9: c = 2 xi sqrt(m k) with k
the tangent stiffness, which for mdr is 2 E* a), frictionless between particles and
mu = 0.02 at the walls. mdr takes only region walls: the die is a region cylinder,
the floor and punch region planes; the punch moves down at a constant speed until
the particles' force on it reaches the target pressure over the die's section.
With LAW = hertz (the control), the same deck under LAMMPS's hertz/material with
LIGGGHTS's restitution 0.051 (the law of liggghts_die_compaction) instead of mdr.
usage: write_deck.py PARTICLES_DATA H0 DIE_DIAMETER DT SPEED PRESSURE RECORDS OUT_DECK [LAW]"""
import math, sys

data, h0, die_d, dt, speed, pressure, records, out = sys.argv[1:9]
law = sys.argv[9] if len(sys.argv) > 9 else "mdr"
h0, die_d, dt, speed, pressure = map(float, (h0, die_d, dt, speed, pressure))
records = int(records)
area = math.pi * (die_d / 2) ** 2
# The stroke that would close a third of the height: far beyond 50 MPa for any law
# that densifies like Hertz (7 %); the run stops at the pressure first.
stroke = h0 / 3
steps = int(round(stroke / speed / dt))
every = max(1, steps // (records * 10))
E, nu, Y, gamma, psi_b, eta = 183e9, 0.318, 800e6, 0.0, 0.5, 1.8
# mdr tangential history needs a stiffness; linear_history's k_t only acts at the
# walls (mu = 0 between particles): 2/7 E R of a median particle, LAMMPS's example's
# choice, which the wall friction 0.02 caps at 0.02 F_n in any case.
kt = 2 / 7 * E * 1.99e-6
mdr = f"mdr {E:e} {nu} {Y:e} {gamma} {psi_b} {eta} damping mdr 1"
if law == "hertz":
    mdr = f"hertz/material {E:e} 0.051 {nu} damping coeff_restitution"
deck = f"""# The flattened NiAl specimen pressed under LAMMPS's mdr model (write_deck.py)
units        si
atom_style   sphere 1
atom_modify  map array
boundary     f f f
newton       off
comm_modify  vel yes
read_data    {data}
neighbor     {0.05 * h0:e} bin
neigh_modify every 1 delay 0 check yes
pair_style   granular
pair_coeff   * * {mdr} tangential linear_history {kt:e} 1.0 0.0
timestep     {dt:e}
variable     dz equal -{speed:e}*elapsed*dt
region       die cylinder z 0 0 {die_d / 2:e} {-h0:e} {3 * h0:e} side in units box
region       floor plane 0 0 0 0 0 1 side in units box
region       punch plane 0 0 {h0:e} 0 0 -1 side in move NULL NULL v_dz units box
variable     wall string "granular {mdr} tangential linear_history {kt:e} 1.0 0.02"
fix          die all wall/gran/region ${{wall}} region die contacts
fix          floor all wall/gran/region ${{wall}} region floor contacts
fix          punch all wall/gran/region ${{wall}} region punch contacts
fix          integr all nve/sphere
compute      fpunch all reduce sum f_punch[4]
compute      ffloor all reduce sum f_floor[4]
variable     height equal {h0:e}+v_dz
variable     punch_pressure equal -c_fpunch/{area:e}
variable     floor_pressure equal c_ffloor/{area:e}
thermo_style custom step time v_height v_punch_pressure v_floor_pressure
thermo_modify norm no lost error format float %.17g
thermo       {every}
fix          stop all halt {every} v_punch_pressure > {pressure:e} error continue
run          {steps}
"""
open(out, "w").write(deck)
