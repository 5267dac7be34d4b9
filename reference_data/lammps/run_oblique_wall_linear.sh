#!/usr/bin/env bash
# Regenerate reference_data/lammps/lammps_oblique_wall_impact_linear/ with LAMMPS 22 Jul
# 2025 (update 4, from .ci/install-lammps): for each combination of normal, damping and
# tangential model below, one LAMMPS process runs every incidence angle (5 to 85 degrees
# from the wall normal, every 10); its log is kept, each angle's final state
# (write_dump) is reduced to one row of results.csv and then deleted.
# usage: reference_data/lammps/run_oblique_wall_linear.sh [OUTDIR]
# OUTDIR (default: the case directory, i.e. re-record) receives the logs and results.csv;
# `tamp crosscheck --live` passes a scratch directory. LMP (default .peers/bin/lmp).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
case_dir=$here/lammps_oblique_wall_impact_linear
out=$(mkdir -p "${1:-$case_dir}" && cd "${1:-$case_dir}" && pwd)
lmp=${LMP:-$here/../../.peers/bin/lmp}
# The scene: a steel sphere R = 1 mm at 1 m/s against a steel plane, mu = 0.3, 1 um
# initial gap, dt = 10 ns, 3000 steps (the contact ends by step 2500 at every angle).
E=2e11; nu=0.3; rho=7800; R=0.001; speed=1.0; gap0=1e-6; mu=0.3
dt=1e-8; nsteps=3000
angles=$(seq 5 10 85)
# The incident velocity components with 17 digits, so that both codes start from the
# same doubles (tamp reads them from results.csv).
read -r -a vt0 < <(python3 -c "import math; print(' '.join('%.17g' % ($speed * math.sin(math.radians(a))) for a in [$(echo $angles | tr ' ' ,)]))")
read -r -a vn0 < <(python3 -c "import math; print(' '.join('%.17g' % ($speed * math.cos(math.radians(a))) for a in [$(echo $angles | tr ' ' ,)]))")
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$case_dir"
rm -f "$out"/log.*.lammps
echo "normal,normal_stiffness,damping,damp,tangential,tangential_stiffness,x_gamma_t,angle_deg,tangential_speed,normal_speed,friction,time_step,steps,youngs_modulus,poisson_ratio,density,radius,initial_gap,vx,vz,omega_y" > "$out/results.csv"
# normal (k_n for hooke, 0 for hertz/material), damping and its damp slot, tangential
# (k_t, 0 for linear_nohistory) and x_gamma_t. Hooke k_n = 2e6 N/m: contact 12.7 us.
# The damp slots of mass_velocity (1/s) and viscoelastic (1/(m s)) give damping ratios
# of 0.03-0.05 at this impact, near coeff_restitution 0.9's.
for run in "hooke 2e6 coeff_restitution 0.9 linear_history 1e6 0.5" \
           "hooke 2e6 coeff_restitution 0.9 linear_nohistory 0 0.5" \
           "hooke 2e6 velocity 0.5 linear_nohistory 0 1" \
           "hertz/material 0 coeff_restitution 0.9 linear_history 1e6 0.5" \
           "hertz/material 0 coeff_restitution 0.9 linear_nohistory 0 0.5" \
           "hooke 2e6 mass_velocity 1.5e4 linear_history 1e6 0.5" \
           "hooke 2e6 viscoelastic 2e8 linear_nohistory 0 0.5" \
           "hertz/material 0 mass_velocity 5e4 linear_nohistory 0 0.5" \
           "hertz/material 0 viscoelastic 1e9 linear_history 1e6 0.5"; do
  read -r normal kn damping damp tangential kt xt <<< "$run"
  if [ "$normal" = hooke ]; then words="hooke $kn $damp"; else words="hertz/material $E $damp $nu"; fi
  if [ "$tangential" = linear_history ]; then twords="linear_history $kt $xt $mu"; else twords="linear_nohistory $xt $mu"; fi
  tag=$(echo "$normal.$damping.$tangential" | tr / _)
  mkdir -p "$scratch/$tag"
  cmd=("$lmp" -in in.oblique_wall -log "$out/log.$tag.lammps" -screen none -nocite
       -var R $R -var rho $rho -var gap0 $gap0 -var normal "$words" -var damping $damping
       -var tangential "$twords" -var dt $dt -var nsteps $nsteps -var dumpdir "$scratch/$tag"
       -var angle $angles -var vt0 "${vt0[@]}" -var vn0 "${vn0[@]}")
  echo "${cmd[*]}" >&2
  "${cmd[@]}"
  i=0
  for angle in $angles; do
    # The last line of the dump: id x y z vx vy vz omegax omegay omegaz.
    read -r _ _ _ _ vx _ vz _ wy _ < <(tail -n 1 "$scratch/$tag/a$angle.dump")
    echo "$normal,$kn,$damping,$damp,$tangential,$kt,$xt,$angle,${vt0[$i]},${vn0[$i]},$mu,$dt,$nsteps,$E,$nu,$rho,$R,$gap0,$vx,$vz,$wy" >> "$out/results.csv"
    i=$((i + 1))
  done
done
cat "$out/results.csv"
