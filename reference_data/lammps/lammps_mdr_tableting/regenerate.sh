#!/usr/bin/env bash
# Record (or re-run) the LAMMPS side of lammps_mdr_tableting: the deck tamp exports from
# verification/lammps_mdr_tableting.scene.json (deck/in.tamp, deck/particles.data), run
# by LAMMPS in deck/. Kept: the walls' displacements and forces every 500 steps
# (walls.csv, the deck's own record), each particle's apparent radius and position at
# the last step (final.csv, from the deck's final.lammps) and log.lammps. deck/ keeps
# only what tamp exported (the case checks it is the deck tamp exports now).
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
"$tamp" export-lammps "$root/verification/lammps_mdr_tableting.scene.json" --out "$out/deck"
(cd "$out/deck" && "$lmp" -in in.tamp -log log.lammps -screen none -nocite)
mv "$out/deck/walls.csv" "$out/deck/log.lammps" "$out/"
awk 'BEGIN { print "id,radius,x,y,z" }
     /^ITEM: ATOMS/ { atoms = 1; next }
     atoms { print $1 "," $3 "," $5 "," $6 "," $7 }' "$out/deck/final.lammps" > "$out/final.csv"
rm -f "$out/deck/dump.lammps" "$out/deck/final.lammps" "$out/deck/mdr.lammps"
