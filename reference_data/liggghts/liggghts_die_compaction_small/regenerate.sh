#!/usr/bin/env bash
# Record (or re-run) the LIGGGHTS side of liggghts_die_compaction_small: for each
# seed, tamp fills, flattens and presses the specimen and exports the pressing as a
# deck that replays tamp's punch stroke (tamp export-liggghts on the die-compaction
# file); LIGGGHTS runs it; the particles' force on punch and floor at every record
# come from LIGGGHTS's thermo output, the densities from tamp's measure of every
# record's frame (import-liggghts-dump --die-stroke). One row per seed and record.
# usage: regenerate.sh [OUTDIR]   (default: this directory, i.e. re-record)
#   $TAMP is the tamp executable (default: tamp on PATH; crosscheck sets it).
#   $SEEDS the seeds (default: 1). The data file and dumps are deleted afterwards
#   (the export rewrites them bit for bit from the scene and the seed).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$(mkdir -p "${1:-$here}" && cd "${1:-$here}" && pwd)
tamp=${TAMP:-tamp}
scene=${SCENE:-$here/../../../verification/liggghts_die_compaction_small.scene.json}
rows=$out/.results.csv.tmp
echo "seed,record,time,height,h0,dt,steps_per_record,tamp_pressure,punch_pressure,floor_pressure,density_specimen,density_rve" > "$rows"
for seed in ${SEEDS:-1}; do
  d=$out/seed$seed
  rm -rf "$d"
  "$tamp" export-liggghts "$scene" --out "$d" --seed "$seed"
  # Screen output on: LIGGGHTS 3.8 crashes reading an STL mesh without a screen.
  (cd "$d" && liggghts -in in.tamp -log log.liggghts > screen.txt)
  "$tamp" import-liggghts-dump "$d/dump.liggghts" --out "$d/measured" --die-stroke "$d/stroke.json" > /dev/null
  python3 "$here/../../die_replay_rows.py" "$d" "$seed" log.liggghts >> "$rows"
  rm -f "$d/dump.liggghts" "$d/particles.data" "$d/measured/trajectory.csv" "$d/screen.txt"
done
mv "$rows" "$out/results.csv"
cat "$out/results.csv"
