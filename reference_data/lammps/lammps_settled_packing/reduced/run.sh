#!/usr/bin/env bash
# One seed of the reduced settled-packing deck (scene.json here: 500 spheres, 0.3 s) in
# LAMMPS on RANKS MPI ranks, measured by tamp; prints one row of results.csv.
# usage: run.sh SEED OUTDIR [RANKS]   ($TAMP: tamp executable; $LMP, $MPIEXEC: default
#   .peers/bin/lmp and .peers/bin/mpiexec of the checkout)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
seed=$1; d=$2; ranks=${3:-1}
tamp=${TAMP:-tamp}
lmp=${LMP:-$here/../../../../.peers/bin/lmp}
mpiexec=${MPIEXEC:-$here/../../../../.peers/bin/mpiexec}
rm -rf "$d"
# Frames every 500 steps: the floor force is averaged over t = 0.2-0.3 s (step 40000 on).
"$tamp" export-lammps "$here/scene.json" --out "$d" --seed "$seed" --dump-every 500 >&2
(cd "$d" && "$mpiexec" -n "$ranks" "$lmp" -in in.tamp -log log.lammps -screen none -nocite)
grep -q "on $ranks procs" "$d/log.lammps"
"$tamp" import-liggghts-dump "$d/dump.lammps" --out "$d/measured" --floor 0 --gravity 9.81 --average-from 40000 >&2
awk -F, -v s="$seed" 'NR > 1 { q[$1] = $2 }
  END { print s "," q["packing_fraction"] "," q["coordination_number"] "," q["floor_force_over_weight"] }' \
  "$d/measured/quantities.csv"
rm -f "$d/dump.lammps" "$d/final.lammps" "$d/particles.data" "$d/measured/trajectory.csv"
