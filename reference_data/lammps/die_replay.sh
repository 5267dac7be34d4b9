#!/usr/bin/env bash
# The LAMMPS side of a die-compaction replay case, recorded in RECORD_DIR from SCENE
# (a die-compaction file): for each seed, tamp fills, flattens and presses the specimen
# and exports the pressing as a LAMMPS deck that replays tamp's punch stroke (tamp
# export-lammps on the die-compaction file); LAMMPS runs it; the particles' force on
# punch and floor at every record come from its thermo output, the densities from
# tamp's measure of every record's frame (import-liggghts-dump --die-stroke reads
# LAMMPS's dump custom too). One row per seed and record, joined by
# reference_data/die_replay_rows.py, the same join as the LIGGGHTS replays.
# usage: die_replay.sh RECORD_DIR SCENE [OUTDIR]   (default OUTDIR: RECORD_DIR, i.e. re-record)
#   $TAMP is the tamp executable (default: tamp on PATH; crosscheck sets it).
#   $LMP the LAMMPS executable (default: .peers/bin/lmp from .ci/install-lammps).
#   $SEEDS the seeds (default: 1). The dumps are deleted afterwards; the deck, its
#   data file and stroke.json are kept (a few hundred kB for 300 particles).
# With an OUTDIR (crosscheck --live), a seed whose deck is recorded in RECORD_DIR runs
# that deck as it is: the export would fill, flatten and press in tamp again (about as
# much CPU as the peer's run) only to write the same files, and the case checks they
# are not stale (the scene's sha256 in the deck, H0, the stroke). Seeds not recorded
# there and a re-record (no OUTDIR) export.
set -euo pipefail
here=$(cd "$1" && pwd)
scene=$2
out=$(mkdir -p "${3:-$here}" && cd "${3:-$here}" && pwd)
tamp=${TAMP:-tamp}
lmp=${LMP:-$here/../../../.peers/bin/lmp}
rows=$out/.results.csv.tmp
echo "seed,record,time,height,h0,dt,steps_per_record,tamp_pressure,punch_pressure,floor_pressure,density_specimen,density_rve" > "$rows"
for seed in ${SEEDS:-1}; do
  d=$out/seed$seed
  rec=$here/seed$seed
  if [ "$out" != "$here" ] && [ -f "$rec/particles.data" ]; then
    # Live: the recorded deck, not a fresh export (which would press in tamp again).
    rm -rf "$d" && mkdir -p "$d"
    cp -r "$rec/in.tamp" "$rec/particles.data" "$rec/stroke.json" "$d/"
  else
    rm -rf "$d"
    "$tamp" export-lammps "$scene" --out "$d" --seed "$seed"
  fi
  (cd "$d" && "$lmp" -in in.tamp -log log.lammps -screen none -nocite)
  "$tamp" import-liggghts-dump "$d/dump.lammps" --out "$d/measured" --die-stroke "$d/stroke.json" > /dev/null
  python3 "$here/../../die_replay_rows.py" "$d" "$seed" log.lammps >> "$rows"
  rm -f "$d/dump.lammps" "$d/measured/trajectory.csv"
done
mv "$rows" "$out/results.csv"
cat "$out/results.csv"
