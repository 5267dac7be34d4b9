#!/usr/bin/env bash
# Record (or re-run) the LAMMPS side of lammps_mdr_contacts: six runs of MDR contacts
# under prescribed motion (common.in), each in its own directory:
#   equal:    in.pair, two 2 um spheres, no adhesion, damping mdr 1 (eta 1.8);
#   adhesive: in.pair, 2 um and 3 um, surface energy 100 J/m^2, damping mdr 2
#             (eta 1e-4 N s/m);
#   bulk:     in.pair, two 2 um spheres with the bulk trigger at 0.99, so that the
#             bulk response acts once 1 % of a sphere's surface is in contact;
#   wall:     in.wall, a 2 um sphere against a plane region wall, damping mdr 1;
#   adhesive_wall: in.wall, the same sphere with surface energy 100 J/m^2 against the
#             wall and none between spheres (the wall fix's own mdr coefficients),
#             damping mdr 2 (eta 1e-4 N s/m);
#   triplet:  in.triplet, three spheres whose outer contact is screened by the middle
#             one (the contact penalty), damping mdr 1.
# rows.py turns each thermo output (every 10 steps) into rows of results.csv.
# usage: regenerate.sh [OUTDIR]   (default: this directory, i.e. re-record)
#   $LMP the LAMMPS executable (default: .peers/bin/lmp from .ci/install-lammps).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$(mkdir -p "${1:-$here}" && cd "${1:-$here}" && pwd)
lmp=${LMP:-$here/../../../.peers/bin/lmp}
rows=$out/.results.csv.tmp
echo "run,step,gap,force_x_1,force_y_1,force_x_2,radius_1,radius_2,radius_3,free_surface_1,free_surface_2,free_surface_3" > "$rows"
run() {
  label=$1 deck=$2; shift 2
  d=$out/$label
  mkdir -p "$d"
  (cd "$d" && "$lmp" -in "$here/$deck" -log log.lammps -screen none -nocite -var here "$here" "$@")
  python3 "$here/rows.py" "$d/log.lammps" "$label" >> "$rows"
}
stiff="-var gamma 0 -var gamma_wall 0 -var eta 1.8 -var dtype 1"
run equal in.pair -var r1 2e-6 -var r2 2e-6 -var psib 0.5 $stiff
run adhesive in.pair -var r1 2e-6 -var r2 3e-6 -var psib 0.5 -var gamma 100 -var gamma_wall 100 -var eta 1e-4 -var dtype 2
run bulk in.pair -var r1 2e-6 -var r2 2e-6 -var psib 0.99 $stiff
run wall in.wall -var psib 0.5 $stiff
run adhesive_wall in.wall -var psib 0.5 -var gamma 0 -var gamma_wall 100 -var eta 1e-4 -var dtype 2
run triplet in.triplet -var psib 0.5 $stiff
mv "$rows" "$out/results.csv"
