#!/usr/bin/env bash
# Record (or re-run) the LAMMPS side of lammps_die_compaction_small: for each seed,
# tamp fills, flattens and presses the specimen and exports the pressing as a
# LAMMPS deck that replays tamp's punch stroke (tamp export-lammps on the
# die-compaction file); LAMMPS runs it; the particles' force on punch and floor at
# every record come from its thermo output, the densities from tamp's measure of
# every record's frame (import-liggghts-dump --die-stroke reads LAMMPS's dump
# custom too). One row per seed and record, joined by ../../die_replay_rows.py, the
# same join as liggghts_die_compaction_small's.
# usage: regenerate.sh [OUTDIR]   (default: this directory, i.e. re-record)
#   $TAMP is the tamp executable (default: tamp on PATH; crosscheck sets it).
#   $LMP the LAMMPS executable (default: .peers/bin/lmp from .ci/install-lammps).
#   $SEEDS the seeds (default: 1). The data file and dumps are deleted afterwards
#   (the export rewrites them bit for bit from the scene and the seed).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$(mkdir -p "${1:-$here}" && cd "${1:-$here}" && pwd)
tamp=${TAMP:-tamp}
lmp=${LMP:-$here/../../../.peers/bin/lmp}
scene=${SCENE:-$here/../../../verification/lammps_die_compaction_small.scene.json}
rows=$out/.results.csv.tmp
echo "seed,record,time,height,h0,dt,steps_per_record,tamp_pressure,punch_pressure,floor_pressure,density_specimen,density_rve" > "$rows"
for seed in ${SEEDS:-1}; do
  d=$out/seed$seed
  rm -rf "$d"
  "$tamp" export-lammps "$scene" --out "$d" --seed "$seed"
  (cd "$d" && "$lmp" -in in.tamp -log log.lammps -screen none -nocite)
  "$tamp" import-liggghts-dump "$d/dump.lammps" --out "$d/measured" --die-stroke "$d/stroke.json" > /dev/null
  python3 "$here/../../die_replay_rows.py" "$d" "$seed" log.lammps >> "$rows"
  rm -f "$d/dump.lammps" "$d/particles.data" "$d/measured/trajectory.csv"
done
mv "$rows" "$out/results.csv"
cat "$out/results.csv"
