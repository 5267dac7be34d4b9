#!/usr/bin/env bash
# Press seed 1's flattened 1751-particle NiAl specimen (the particles.data that
# liggghts_die_compaction recorded for its frictionless pressing: tamp's fill and
# flatten of nial_die_compaction) under LAMMPS's mdr model and write results.csv.
# Then the control: the same deck under hertz/material (hertz/: in.hertz, log.hertz,
# results.csv). About 23 + 4 min of one core (LAMMPS 22 Jul 2025).
# usage: regenerate.sh [OUTDIR]   (default: this directory)
#   $LMP is the LAMMPS executable (default: .peers/bin/lmp of the repository).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$here/../../..
out=$(mkdir -p "${1:-$here}" && cd "${1:-$here}" && pwd)
lmp=${LMP:-$root/.peers/bin/lmp}
data=$root/reference_data/liggghts/liggghts_die_compaction/mu0/seed1/particles.data
h0=9.71589445381175e-05     # the specimen's H0 (stroke.json of that recording)
die=5.8e-5                  # die diameter, m
dt=1.6771488469601676e-10   # tamp's step for this specimen (same recording)
# Four times tamp's mean punch speed to 50 MPa under Hertz (6.4 % of H0 in 1e-4 s);
# PROVENANCE.md says why that is still quasi-static.
speed=$(python3 -c "print(4 * 0.064 * $h0 / 1e-4)")
mkdir -p "$out/hertz"
cp "$data" "$out/particles.data"
cp "$data" "$out/hertz/particles.data"
python3 "$here/write_deck.py" particles.data $h0 $die $dt "$speed" 50e6 50 "$out/in.mdr"
python3 "$here/write_deck.py" particles.data $h0 $die $dt "$speed" 50e6 50 "$out/hertz/in.hertz" hertz
for run in mdr hertz/hertz; do
  dir=$out/$(dirname $run) name=$(basename $run)
  (cd "$dir" && "$lmp" -in in.$name -log log.$name -screen none -nocite)
  python3 "$here/extract.py" "$dir/log.$name" "$dir/particles.data" $die > "$dir/.results.csv.tmp"
  mv "$dir/.results.csv.tmp" "$dir/results.csv"
  rm -f "$dir/particles.data"
done
