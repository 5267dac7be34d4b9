#!/usr/bin/env bash
# Record (or re-run) the LAMMPS side of lammps_die_press_cycle: tamp fills, flattens,
# presses and unloads the specimen and exports its cycle as a LAMMPS deck
# (tamp export-lammps on the die-compaction file: the stroke to the peak, the
# unloading rise, the ejection); LAMMPS runs it; rows.py turns its thermo output
# into results.csv, one row per record.
# usage: regenerate.sh [OUTDIR]   (default: this directory, i.e. re-record)
#   $TAMP is the tamp executable (default: tamp on PATH; crosscheck sets it).
#   $LMP the LAMMPS executable (default: .peers/bin/lmp from .ci/install-lammps).
#   $SEEDS the seeds (default: 1; "2 3" give the spread the tolerances take).
# With an OUTDIR (crosscheck --live), a seed whose deck is recorded here runs that
# deck as it is (the export would press in tamp again only to write the same files;
# the case checks they are current). A re-record also runs LAMMPS's mdr cycle of the
# same specimen (mdr/, drawn beside the comparison).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$(mkdir -p "${1:-$here}" && cd "${1:-$here}" && pwd)
tamp=${TAMP:-tamp}
lmp=${LMP:-$here/../../../.peers/bin/lmp}
scene=${SCENE:-$here/../../../verification/lammps_die_press_cycle.scene.json}
rows=$out/.results.csv.tmp
columns="seed,step,punch_face,floor_rise,punch_force,floor_force,floor_force_mean,die_axial_force,die_radial_force,mean_square_radius,top"
echo "$columns" > "$rows"
for seed in ${SEEDS:-1}; do
  d=$out/seed$seed
  rec=$here/seed$seed
  if [ "$out" != "$here" ] && [ -f "$rec/particles.data" ]; then
    rm -rf "$d" && mkdir -p "$d"
    cp "$rec/in.tamp" "$rec/particles.data" "$rec/stroke.json" "$rec/cycle.json" "$d/"
  else
    rm -rf "$d"
    "$tamp" export-lammps "$scene" --out "$d" --seed "$seed"
  fi
  (cd "$d" && "$lmp" -in in.tamp -log log.lammps -screen none -nocite)
  python3 "$here/rows.py" "$d" "$seed" log.lammps >> "$rows"
done
mv "$rows" "$out/results.csv"
if [ "$out" = "$here" ]; then
  mkdir -p "$here/mdr"
  cp "$here/seed1/particles.data" "$here/mdr/particles.data"
  python3 "$here/mdr/write_deck.py" "$here/seed1/cycle.json" "$here/mdr/in.mdr"
  (cd "$here/mdr" && "$lmp" -in in.mdr -log log.mdr -screen none -nocite)
  python3 "$here/mdr/rows.py" "$here/mdr/log.mdr" "$here/seed1/cycle.json" > "$here/mdr/.results.csv.tmp"
  mv "$here/mdr/.results.csv.tmp" "$here/mdr/results.csv"
fi
