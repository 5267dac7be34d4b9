#!/usr/bin/env bash
# Record (or re-run) the LAMMPS side of lammps_mdr_triaxial: the deck tamp exports from
# verification/lammps_mdr_triaxial.scene.json (deck/in.tamp, deck/particles.data), run
# by LAMMPS in deck/. Its dump becomes trajectory.csv (and quantities.csv) through
# `tamp import-liggghts-dump`; the walls' displacements and forces are the deck's own
# walls.csv (the scene sets output.walls); each particle's free-surface fraction goes from
# the deck's mdr.lammps to free_surface.csv; its log is log.lammps. deck/ keeps only what
# tamp exported (the case checks it is the deck tamp exports now); the dumps are not kept.
# usage: regenerate.sh [OUTDIR]   (default: this directory, i.e. re-record)
#   $LMP the LAMMPS executable (default: .peers/bin/lmp from .ci/install-lammps);
#   $TAMP the tamp executable (default: target/release/tamp of this checkout).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$here/../../..
out=$(mkdir -p "${1:-$here}" && cd "${1:-$here}" && pwd)
lmp=${LMP:-$root/.peers/bin/lmp}
tamp=${TAMP:-$root/target/release/tamp}
rm -rf "$out/deck"
"$tamp" export-lammps "$root/verification/lammps_mdr_triaxial.scene.json" --out "$out/deck"
(cd "$out/deck" && "$lmp" -in in.tamp -log log.lammps -screen none -nocite)
"$tamp" import-liggghts-dump "$out/deck/dump.lammps" --out "$out"
mv "$out/deck/walls.csv" "$out/deck/log.lammps" "$out/"
# fix granular/mdr's free-surface fraction of every particle at the same steps.
awk 'BEGIN { print "step,id,free_surface" }
     /^ITEM: TIMESTEP/ { getline; step = $1; next }
     /^ITEM:/ { atoms = ($2 == "ATOMS"); next }
     atoms && NF == 2 { print step "," $1 "," $2 }' "$out/deck/mdr.lammps" > "$out/free_surface.csv"
rm -f "$out/deck/dump.lammps" "$out/deck/final.lammps" "$out/deck/mdr.lammps"
