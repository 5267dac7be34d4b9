#!/usr/bin/env bash
# Record (or re-run) the LAMMPS side of lammps_mdr_deep_pair: in.deep, a 1 um and a 3 um
# sphere pressed until the small one's share of the overlap passes both caps a side may
# have, then held still; its thermo output (every 10 steps) becomes results.csv.
# usage: regenerate.sh [OUTDIR]   (default: this directory, i.e. re-record)
#   $LMP the LAMMPS executable (default: .peers/bin/lmp from .ci/install-lammps).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$(mkdir -p "${1:-$here}" && cd "${1:-$here}" && pwd)
lmp=${LMP:-$here/../../../.peers/bin/lmp}
work=$(mktemp -d)
(cd "$work" && "$lmp" -in "$here/in.deep" -log log.lammps -screen none -nocite)
{
  echo "step,gap,force_x_1,mean_displacement_increment_1,mean_displacement_increment_2,free_surface_1,free_surface_2"
  awk '$1 == "Step" && $2 == "v_gap" { inside = 1; next }
       inside && $1 == "Loop" { exit }
       inside { $1 = $1; gsub(/ /, ","); print }' "$work/log.lammps"
} > "$out/.results.csv.tmp"
mv "$out/.results.csv.tmp" "$out/results.csv"
rm -rf "$work"
