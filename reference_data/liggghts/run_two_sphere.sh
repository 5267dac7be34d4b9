#!/usr/bin/env bash
# Regenerate reference_data/liggghts/liggghts_two_sphere_<model>/ with the installed
# LIGGGHTS: one run per restitution, its log kept, its per-step dump reduced by
# two_sphere_extract.py to one row of results.csv and then deleted (3.8 MB each).
# usage: reference_data/liggghts/run_two_sphere.sh hertz|hooke [OUTDIR]
# OUTDIR (default: the case directory, i.e. re-record) receives the logs and
# results.csv; `tamp crosscheck --live` passes a scratch directory.
set -euo pipefail
model=$1
here=$(cd "$(dirname "$0")" && pwd)
case_dir=$here/liggghts_two_sphere_$model
out=$(mkdir -p "${2:-$case_dir}" && cd "${2:-$case_dir}" && pwd)
# The scene: steel spheres R = 1 mm, 1 m/s relative speed, 2 um initial gap, dt = 1 ns.
E=2e11; nu=0.3; rho=7800; R=0.001; v0=0.5; gap0=2e-6; mu=0.5; charvel=1.0
dt=1e-9; nsteps=12000
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$case_dir"
python3 "$here/two_sphere_extract.py" --header > "$out/results.csv"
for e in 0.5 0.9 0.99; do
  cmd=(liggghts -in in.two_sphere -log "$out/log.e$e.liggghts" -screen none
       -var E $E -var nu $nu -var rho $rho -var R $R -var v0 $v0 -var gap0 $gap0
       -var e $e -var mu $mu -var charvel $charvel -var dt $dt -var nsteps $nsteps
       -var dumpfile "$scratch/e$e.dump")
  echo "${cmd[*]}" >&2
  "${cmd[@]}"
  python3 "$here/two_sphere_extract.py" "$scratch/e$e.dump" $model $E $nu $rho $R $v0 $gap0 $e $charvel $dt >> "$out/results.csv"
done
cat "$out/results.csv"
