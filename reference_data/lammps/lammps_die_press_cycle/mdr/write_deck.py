#!/usr/bin/env python3
"""Write the LAMMPS deck of the mdr press cycle drawn beside lammps_die_press_cycle:
seed 1's flattened specimen (particles.data of the Hertz deck) pressed, unloaded
and ejected under LAMMPS's mdr normal model (Zunker & Kamrin 2024; E and nu of
NiAl, yield stress 800 MPa as nial_die_compaction_mdr, no adhesion, psi_b 0.5, mdr
damping with eta_n0 = 2 xi = 1.8) and the Hertz deck's friction (0.5 between
particles, 0.3 at the walls, tangential linear_history with k_t = 2/7 E R of a
2.5 um particle). mdr has no counterpart in tamp, so the motion is load-controlled
as tamp's own cycle is, in three runs:
  press:  the punch moves down at the Hertz pressing's mean speed until the push
          on it exceeds 50 MPa over the die's section (fix halt);
  unload: it rises at the unloading speed until the particles no longer push on it;
  eject:  it is taken away and the floor rises as in the Hertz deck (the same ramp
          and speed) to the die's mouth.
A new run starts a moving region at rest for one step (Region::set_velocity):
negligible beside the stage's own change of speed. The box is shrink-wrapped
(boundary m): the ejected mdr compact sheds particles past the Hertz deck's fixed box.
usage: write_deck.py CYCLE_JSON OUT_DECK"""
import json, math, sys

c = json.load(open(sys.argv[1]))
cycle, die_d = c["cycle"], c["die_diameter"]
press = cycle["press"]
h0, dt, k = press["h0"], press["dt"], cycle["record_steps"]
press_time = press["interval"] * len(press["heights"])
v_press = (h0 - press["heights"][-1]) / press_time
v_unload = cycle["unload_rise_per_step"] / dt
v, tr = cycle["eject_speed"], cycle["eject_ramp"]
area = math.pi * (die_d / 2) ** 2
E, nu, Y, gamma, psi_b, eta = 183e9, 0.318, 800e6, 0.0, 0.5, 1.8
kt = 2 / 7 * E * 2.5e-6
mdr = f"mdr {E:e} {nu} {Y:e} {gamma} {psi_b} {eta} damping mdr 1"
deck = f"""# The mdr press cycle of lammps_die_press_cycle's specimen (write_deck.py)
units        si
atom_style   sphere 1
atom_modify  map array
boundary     m m m
newton       off
comm_modify  vel yes
read_data    particles.data
neighbor     {0.05 * h0:e} bin
neigh_modify every 1 delay 0 check yes
pair_style   granular
pair_coeff   * * {mdr} tangential linear_history {kt:e} 1.0 0.5
timestep     {dt!r}
fix          gravi all gravity 9.81 vector 0 0 -1
variable     dz equal -{v_press!r}*step*{dt!r}
variable     fz equal 0
region       die cylinder z 0 0 {die_d / 2!r} 0 {h0!r} side in open 1 open 2 units box
region       floor plane 0 0 0 0 0 1 side in move NULL NULL v_fz units box
region       punch plane 0 0 {h0!r} 0 0 -1 side in move NULL NULL v_dz units box
variable     wall string "granular {mdr} tangential linear_history {kt:e} 1.0 0.3"
fix          die all wall/gran/region ${{wall}} region die contacts
fix          floor all wall/gran/region ${{wall}} region floor contacts
fix          punch all wall/gran/region ${{wall}} region punch contacts
fix          integr all nve/sphere
compute      fpunch all reduce sum f_punch[4]
compute      ffloor all reduce sum f_floor[4]
variable     punch_fz equal -c_fpunch
variable     floor_push equal c_ffloor
fix          pushmean all ave/time 1 {k} {k} v_floor_push
thermo_style custom step v_dz v_fz v_punch_fz v_floor_push f_pushmean
thermo_modify norm no lost ignore format float %.17g
thermo       {k}
# press to 50 MPa
fix          stop all halt 1 v_punch_fz > {50e6 * area!r} error continue
run          {int(round(0.3 * h0 / v_press / dt))}
unfix        stop
# unload until released
variable     z0 equal $(v_dz:%.17g)
variable     s0 equal $(step)
variable     dz equal v_z0+{v_unload * dt!r}*(step-v_s0)
fix          stop all halt 1 v_punch_fz <= 0 error continue
run          {int(round(0.3 * h0 / v_unload / dt))}
unfix        stop
# eject: the punch away, the floor up to the mouth
variable     z1 equal $(v_dz:%.17g)
variable     s1 equal $(step)
variable     dz equal v_z1+{2 * h0!r}
variable     te equal (step-v_s1)*{dt!r}
variable     rise equal ternary(v_te<{tr!r},{0.5 * v / tr!r}*v_te^2,{v!r}*(v_te-{0.5 * tr!r}))
variable     fz equal ternary(v_rise<{h0!r},v_rise,{h0!r})
run          {cycle["eject_steps"]}
"""
open(sys.argv[2], "w").write(deck)
