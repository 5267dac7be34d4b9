#!/usr/bin/env bash
# Regenerate reference_data/liggghts/liggghts_oblique_wall_impact/ with the installed
# LIGGGHTS: one run per incidence angle (5 to 85 degrees from the wall normal, every 5),
# its log kept, its dump (steps 0 and nsteps only) reduced by
# oblique_wall_impact_extract.py to one row of results.csv and then deleted.
# usage: reference_data/liggghts/run_oblique_wall_impact.sh [OUTDIR]
# OUTDIR (default: the case directory, i.e. re-record) receives the logs and results.csv;
# `tamp crosscheck --live` passes a scratch directory.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
case_dir=$here/liggghts_oblique_wall_impact
out=$(mkdir -p "${1:-$case_dir}" && cd "${1:-$case_dir}" && pwd)
# The scene: a steel sphere R = 1 mm at 1 m/s against a steel plane, e = 0.9, mu = 0.3,
# 1 um initial gap, dt = 10 ns, 3000 steps (at 85 degrees the contact ends by step 2400).
E=2e11; nu=0.3; rho=7800; R=0.001; speed=1.0; gap0=1e-6; e=0.9; mu=0.3
dt=1e-8; nsteps=3000
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$case_dir"
rm -f "$out"/log.*.liggghts
python3 "$here/oblique_wall_impact_extract.py" --header > "$out/results.csv"
for angle in $(seq 5 5 85); do
  # The incident velocity components, printed with 17 digits so that both codes start
  # from the same doubles (tamp reads them from results.csv).
  read -r vt0 vn0 < <(python3 -c "import math; a = math.radians($angle); \
print('%.17g %.17g' % ($speed * math.sin(a), $speed * math.cos(a)))")
  cmd=(liggghts -in in.oblique_wall_impact -log "$out/log.a$angle.liggghts" -screen none
       -var E $E -var nu $nu -var rho $rho -var R $R -var vt0 $vt0 -var vn0 $vn0
       -var gap0 $gap0 -var e $e -var mu $mu -var dt $dt -var nsteps $nsteps
       -var dumpfile "$scratch/a$angle.dump" -var dumpevery $nsteps)
  echo "${cmd[*]}" >&2
  "${cmd[@]}"
  python3 "$here/oblique_wall_impact_extract.py" "$scratch/a$angle.dump" $angle $E $nu $rho \
    $R $vt0 $vn0 $gap0 $e $mu $dt >> "$out/results.csv"
done
cat "$out/results.csv"
