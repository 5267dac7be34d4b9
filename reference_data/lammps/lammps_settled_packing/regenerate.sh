#!/usr/bin/env bash
# Record (or re-run) the LAMMPS side of lammps_settled_packing: for seeds 1-10, export
# the case's scene with that seed (tamp places the same 2000 spheres both codes start
# from), run LAMMPS on one rank, measure the final frame with tamp's measures, and
# collect one row per seed in results.csv.
# usage: regenerate.sh [OUTDIR]   (default: this directory, i.e. re-record)
#   $TAMP is the tamp executable (default: tamp on PATH; crosscheck sets it);
#   $LMP the LAMMPS executable (default: .peers/bin/lmp of the checkout).
# The seeds' particles.data and dumps are deleted afterwards (export rewrites them).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$(mkdir -p "${1:-$here}" && cd "${1:-$here}" && pwd)
tamp=${TAMP:-tamp}
lmp=${LMP:-$here/../../../.peers/bin/lmp}
scene=$here/../../../verification/lammps_settled_packing.scene.json
# The scene's gravity is 9.81 m/s² along -z and its floor the plane z = 0.
rows=$out/.results.csv.tmp
echo "seed,packing_fraction,coordination_number,bottom_wall_force_over_weight,bed_height,mean_speed" > "$rows"
for seed in 1 2 3 4 5 6 7 8 9 10; do
  d=$out/seed$seed
  rm -rf "$d"
  # Frames every 500 steps: the floor force is averaged over t = 0.4-0.5 s (step 80000 on).
  "$tamp" export-lammps "$scene" --out "$d" --seed "$seed" --dump-every 500
  (cd "$d" && "$lmp" -in in.tamp -log log.lammps -screen none -nocite)
  "$tamp" import-liggghts-dump "$d/dump.lammps" --out "$d/measured" --floor 0 --gravity 9.81 --average-from 80000
  awk -F, -v s="$seed" 'NR > 1 { q[$1] = $2 }
    END { print s "," q["packing_fraction"] "," q["coordination_number"] "," q["floor_force_over_weight"] "," q["bed_height"] "," q["mean_speed"] }' \
    "$d/measured/quantities.csv" >> "$rows"
  rm -f "$d/dump.lammps" "$d/final.lammps" "$d/particles.data" "$d/measured/trajectory.csv"
done
mv "$rows" "$out/results.csv"
cat "$out/results.csv"
