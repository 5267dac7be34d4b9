#!/usr/bin/env bash
# Regenerate reference_data/liggghts/liggghts_two_sphere_oblique/ with the installed
# LIGGGHTS: one run per (model, e, mu), its log kept, its dump (steps 0 and nsteps only)
# reduced by two_sphere_oblique_extract.py to one row of results.csv and then deleted.
# usage: reference_data/liggghts/run_two_sphere_oblique.sh [OUTDIR]
# OUTDIR (default: the case directory, i.e. re-record) receives the logs and results.csv;
# `tamp crosscheck --live` passes a scratch directory.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
case_dir=$here/liggghts_two_sphere_oblique
out=$(mkdir -p "${1:-$case_dir}" && cd "${1:-$case_dir}" && pwd)
# The scene: steel spheres R = 1 mm, velocities +-(0.5, 0.25, 0) m/s, 2 um initial gap,
# dt = 10 ns, 1200 steps (the contact ends before step 900).
E=2e11; nu=0.3; rho=7800; R=0.001; v0=0.5; vt0=0.25; gap0=2e-6; charvel=1.0
dt=1e-8; nsteps=1200
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$case_dir"
python3 "$here/two_sphere_oblique_extract.py" --header > "$out/results.csv"
for run in hertz:0.5:0.1 hertz:0.5:0.3 hertz:0.5:1.0 hertz:0.9:0.3 hooke:0.5:0.3 hooke:0.5:1.0; do
  IFS=: read -r model e mu <<< "$run"
  tag=$model.e$e.mu$mu
  cmd=(liggghts -in in.two_sphere_oblique -log "$out/log.$tag.liggghts" -screen none
       -var model $model -var E $E -var nu $nu -var rho $rho -var R $R -var v0 $v0
       -var vt0 $vt0 -var gap0 $gap0 -var e $e -var mu $mu -var charvel $charvel
       -var dt $dt -var nsteps $nsteps -var dumpfile "$scratch/$tag.dump"
       -var dumpevery $nsteps)
  echo "${cmd[*]}" >&2
  "${cmd[@]}"
  python3 "$here/two_sphere_oblique_extract.py" "$scratch/$tag.dump" $model $E $nu $rho $R \
    $v0 $vt0 $gap0 $e $mu $charvel $dt >> "$out/results.csv"
done
cat "$out/results.csv"
