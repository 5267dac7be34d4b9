#!/usr/bin/env bash
# Record (or re-run) the LAMMPS side of lammps_mdr_two_sphere: in.two run twice,
#   equal:    two 2 um NiAl spheres, no adhesion, damping mdr 1 (eta 1.8);
#   adhesive: 2 um and 3 um spheres, surface energy 20 J/m^2, damping mdr 2
#             (eta 1e-4 N s/m);
# rows.py turns each thermo output (every 10 steps) into rows of results.csv.
# usage: regenerate.sh [OUTDIR]   (default: this directory, i.e. re-record)
#   $LMP the LAMMPS executable (default: .peers/bin/lmp from .ci/install-lammps).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$(mkdir -p "${1:-$here}" && cd "${1:-$here}" && pwd)
lmp=${LMP:-$here/../../../.peers/bin/lmp}
rows=$out/.results.csv.tmp
echo "run,step,gap,force,radius_1,radius_2,free_surface_1,free_surface_2" > "$rows"
run() {
  label=$1; shift
  d=$out/$label
  mkdir -p "$d"
  (cd "$d" && "$lmp" -in "$here/in.two" -log log.lammps -screen none -nocite "$@")
  python3 "$here/rows.py" "$d/log.lammps" "$label" >> "$rows"
}
run equal -var r1 2e-6 -var r2 2e-6 -var gamma 0 -var eta 1.8 -var dtype 1
run adhesive -var r1 2e-6 -var r2 3e-6 -var gamma 20 -var eta 1e-4 -var dtype 2
mv "$rows" "$out/results.csv"
