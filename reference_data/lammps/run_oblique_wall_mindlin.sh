#!/usr/bin/env bash
# Regenerate reference_data/lammps/lammps_oblique_wall_impact_mindlin/ with LAMMPS 22 Jul
# 2025 (update 4, from .ci/install-lammps): for each tangential model (with its x_gamma_t,
# and damping), one LAMMPS process runs every incidence angle (5 to 85 degrees from the wall normal, every
# 10); its log is kept, each angle's final state (write_dump) is reduced to one row of
# results.csv and then deleted.
# usage: reference_data/lammps/run_oblique_wall_mindlin.sh [OUTDIR]
# OUTDIR (default: the case directory, i.e. re-record) receives the logs and results.csv;
# `tamp crosscheck --live` passes a scratch directory. LMP (default .peers/bin/lmp).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
case_dir=$here/lammps_oblique_wall_impact_mindlin
out=$(mkdir -p "${1:-$case_dir}" && cd "${1:-$case_dir}" && pwd)
lmp=${LMP:-$here/../../.peers/bin/lmp}
# The scene: a steel sphere R = 1 mm at 1 m/s against a steel plane, mu = 0.3, 1 um
# initial gap, dt = 10 ns, 3000 steps (the contact ends by step 2400 at every angle).
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
echo "tangential,damping,restitution_in,x_gamma_t,angle_deg,tangential_speed,normal_speed,friction,time_step,steps,youngs_modulus,poisson_ratio,density,radius,initial_gap,vx,vz,omega_y" > "$out/results.csv"
# Each tangential model with damping coeff_restitution e = 0.9 and no tangential dashpot
# (x_gamma_t = 0); mindlin/force undamped (damping velocity, damp 0), the LAMMPS model of
# tamp's mindlin_no_slip; and each tangential model again with the dashpot x_gamma_t = 0.5.
for run in "mindlin 0 coeff_restitution 0.9" "mindlin/force 0 coeff_restitution 0.9" \
           "mindlin_rescale 0 coeff_restitution 0.9" "mindlin_rescale/force 0 coeff_restitution 0.9" \
           "mindlin/force 0 velocity 0" \
           "mindlin 0.5 coeff_restitution 0.9" "mindlin/force 0.5 coeff_restitution 0.9" \
           "mindlin_rescale 0.5 coeff_restitution 0.9" "mindlin_rescale/force 0.5 coeff_restitution 0.9"; do
  read -r tangential xt damping e <<< "$run"
  tag=$(echo "$tangential.$damping" | tr / _)
  # The dashpot runs' logs carry x_gamma_t in their names; the undamped ones keep theirs.
  [ "$xt" = 0 ] || tag=$tag.xt$xt
  mkdir -p "$scratch/$tag"
  cmd=("$lmp" -in in.oblique_wall -log "$out/log.$tag.lammps" -screen none -nocite
       -var E $E -var nu $nu -var rho $rho -var R $R -var gap0 $gap0 -var e $e
       -var damping $damping -var tangential $tangential -var xt $xt -var mu $mu -var dt $dt
       -var nsteps $nsteps -var dumpdir "$scratch/$tag"
       -var angle $angles -var vt0 "${vt0[@]}" -var vn0 "${vn0[@]}")
  echo "${cmd[*]}" >&2
  "${cmd[@]}"
  i=0
  for angle in $angles; do
    # The last line of the dump: id x y z vx vy vz omegax omegay omegaz.
    read -r _ _ _ _ vx _ vz _ wy _ < <(tail -n 1 "$scratch/$tag/a$angle.dump")
    echo "$tangential,$damping,$e,$xt,$angle,${vt0[$i]},${vn0[$i]},$mu,$dt,$nsteps,$E,$nu,$rho,$R,$gap0,$vx,$vz,$wy" >> "$out/results.csv"
    i=$((i + 1))
  done
done
cat "$out/results.csv"
