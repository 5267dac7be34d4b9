#!/usr/bin/env bash
# Regenerate reference_data/lammps/lammps_two_sphere_hertz/ with LAMMPS 22 Jul 2025
# (update 4, from .ci/install-lammps): one run per damping model and damp coefficient, its log
# kept, its per-step dump reduced by ../liggghts/two_sphere_extract.py (the same
# definitions as the LIGGGHTS case; its `model` column holds the LAMMPS damping model)
# to one row of results.csv and then deleted (3.8 MB each).
# usage: reference_data/lammps/run_two_sphere.sh [OUTDIR]
# OUTDIR (default: the case directory, i.e. re-record) receives the logs and
# results.csv; `tamp crosscheck --live` passes a scratch directory.
# LMP (default: .peers/bin/lmp from .ci/install-lammps) is the LAMMPS executable; not
# the Debian package's lmp (LAMMPS 2022), which has no damping coeff_restitution.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
case_dir=$here/lammps_two_sphere_hertz
out=$(mkdir -p "${1:-$case_dir}" && cd "${1:-$case_dir}" && pwd)
lmp=${LMP:-$here/../../.peers/bin/lmp}
# The scene: steel spheres R = 1 mm, 1 m/s relative speed, 2 um initial gap, dt = 1 ns.
E=2e11; nu=0.3; rho=7800; R=0.001; v0=0.5; gap0=2e-6
dt=1e-9; nsteps=12000
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$case_dir"
python3 "$here/../liggghts/two_sphere_extract.py" --header > "$out/results.csv"
# coeff_restitution and tsuji take e in the damp slot; mass_velocity (1/s) and
# viscoelastic (1/(m s)) take eta_n0, chosen for damping ratios near 0.05 at this impact.
for run in "coeff_restitution 0.5" "coeff_restitution 0.9" "coeff_restitution 0.99" \
           "tsuji 0.5" "tsuji 0.9" "tsuji 0.99" "mass_velocity 5e4" "viscoelastic 2e9"; do
  read -r damping e <<< "$run"
  cmd=("$lmp" -in in.two_sphere -log "$out/log.$damping.e$e.lammps" -screen none -nocite
       -var E $E -var nu $nu -var rho $rho -var R $R -var v0 $v0 -var gap0 $gap0
       -var e $e -var damping $damping -var dt $dt -var nsteps $nsteps
       -var dumpfile "$scratch/$damping.e$e.dump")
  echo "${cmd[*]}" >&2
  "${cmd[@]}"
  # characteristic_velocity (a LIGGGHTS model hooke input) does not exist here: 0.
  python3 "$here/../liggghts/two_sphere_extract.py" "$scratch/$damping.e$e.dump" $damping \
    $E $nu $rho $R $v0 $gap0 $e 0 $dt >> "$out/results.csv"
done
cat "$out/results.csv"
