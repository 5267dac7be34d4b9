#!/usr/bin/env bash
# Regenerate reference_data/lammps/lammps_cylinder_wall_impact/ with LAMMPS 22 Jul 2025
# (update 4, from .ci/install-lammps): for each tangential model, one LAMMPS process runs
# every incidence angle (5 to 85 degrees from the wall normal, every 10) of a sphere
# against the inside of a cylinder (in.cylinder_wall); its log is kept, each angle's
# final state and contact step count are reduced to one row of results.csv and deleted.
# usage: reference_data/lammps/run_cylinder_wall.sh [OUTDIR]
# OUTDIR (default: the case directory, i.e. re-record) receives the logs and results.csv;
# `tamp crosscheck --live` passes a scratch directory. LMP (default .peers/bin/lmp).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
case_dir=$here/lammps_cylinder_wall_impact
out=$(mkdir -p "${1:-$case_dir}" && cd "${1:-$case_dir}" && pwd)
lmp=${LMP:-$here/../../.peers/bin/lmp}
# The scene: a steel sphere R = 1 mm at 1 m/s against the inside of a steel cylinder
# Rc = 2.5 mm (ends y = -L, L closed by planes), mu = 0.3, 1 um initial gap, dt = 10 ns,
# 3000 steps, damping coeff_restitution e = 0.9.
E=2e11; nu=0.3; rho=7800; R=0.001; Rc=0.0025; L=0.005; speed=1.0; gap0=1e-6; mu=0.3
e=0.9; damping=coeff_restitution; dt=1e-8; nsteps=3000
angles=$(seq 5 10 85)
# The incident velocity components with 17 digits (tamp reads them from results.csv).
read -r -a vt0 < <(python3 -c "import math; print(' '.join('%.17g' % ($speed * math.sin(math.radians(a))) for a in [$(echo $angles | tr ' ' ,)]))")
read -r -a vn0 < <(python3 -c "import math; print(' '.join('%.17g' % ($speed * math.cos(math.radians(a))) for a in [$(echo $angles | tr ' ' ,)]))")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$case_dir"
rm -f "$out"/log.*.lammps
echo "tangential,damping,restitution_in,angle_deg,tangential_speed,normal_speed,friction,time_step,steps,youngs_modulus,poisson_ratio,density,radius,initial_gap,cylinder_radius,vx,vz,omega_y,contact_steps" > "$out/results.csv"
for tangential in mindlin mindlin/force; do
  tag=$(echo "$tangential.$damping" | tr / _)
  mkdir -p "$scratch/$tag"
  cmd=("$lmp" -in in.cylinder_wall -log "$out/log.$tag.lammps" -screen none -nocite
       -var E $E -var nu $nu -var rho $rho -var R $R -var Rc $Rc -var L $L -var gap0 $gap0
       -var e $e -var damping $damping -var tangential $tangential -var mu $mu -var dt $dt
       -var nsteps $nsteps -var dumpdir "$scratch/$tag"
       -var angle $angles -var vt0 "${vt0[@]}" -var vn0 "${vn0[@]}")
  echo "${cmd[*]}" >&2
  "${cmd[@]}"
  i=0
  for angle in $angles; do
    # The last line of the dump: id x y z vx vy vz omegax omegay omegaz.
    read -r _ _ _ _ vx _ vz _ wy _ < <(tail -n 1 "$scratch/$tag/a$angle.dump")
    steps=$(python3 -c "print(round(float(open('$scratch/$tag/a$angle.steps').read())))")
    echo "$tangential,$damping,$e,$angle,${vt0[$i]},${vn0[$i]},$mu,$dt,$nsteps,$E,$nu,$rho,$R,$gap0,$Rc,$vx,$vz,$wy,$steps" >> "$out/results.csv"
    i=$((i + 1))
  done
done
cat "$out/results.csv"
