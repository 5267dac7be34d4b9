#!/usr/bin/env bash
# Record (or re-run) the LIGGGHTS side of liggghts_die_compaction_small: for each
# seed, tamp fills, flattens and presses the specimen and exports the pressing as a
# deck that replays tamp's punch stroke (tamp export-liggghts on the die-compaction
# file); LIGGGHTS runs it; the particles' force on punch and floor at every record
# come from LIGGGHTS's thermo output, the densities from tamp's measure of every
# record's frame (import-liggghts-dump --die-stroke). One row per seed and record.
# usage: regenerate.sh [OUTDIR]   (default: this directory, i.e. re-record)
#   $TAMP is the tamp executable (default: tamp on PATH; crosscheck sets it).
#   $SEEDS the seeds (default: 1). The dumps are deleted afterwards; the deck, its
#   data file and stroke.json are kept (a few hundred kB for 300 particles).
# With an OUTDIR (crosscheck --live), a seed whose deck is recorded here runs that
# deck as it is: the export would fill, flatten and press in tamp again (about as
# much CPU as the peer's run) only to write the same files, and the quick-tier case
# checks they are not stale (the scene's sha256 in the deck, H0, the stroke). Seeds
# not recorded here (the spread's, SEEDS="2 3") and a re-record (no OUTDIR) export.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$(mkdir -p "${1:-$here}" && cd "${1:-$here}" && pwd)
tamp=${TAMP:-tamp}
scene=${SCENE:-$here/../../../verification/liggghts_die_compaction_small.scene.json}
# Where the recorded decks are (liggghts_die_compaction passes one per pressing).
recorded=${RECORDED:-$here}
rows=$out/.results.csv.tmp
echo "seed,record,time,height,h0,dt,steps_per_record,tamp_pressure,punch_pressure,floor_pressure,density_specimen,density_rve" > "$rows"
for seed in ${SEEDS:-1}; do
  d=$out/seed$seed
  rec=$recorded/seed$seed
  if [ "$out" != "$recorded" ] && [ -f "$rec/particles.data" ]; then
    # Live: the recorded deck, not a fresh export (which would press in tamp again).
    rm -rf "$d" && mkdir -p "$d"
    cp -r "$rec/in.tamp" "$rec/particles.data" "$rec/stroke.json" "$rec/meshes" "$d/"
  else
    rm -rf "$d"
    "$tamp" export-liggghts "$scene" --out "$d" --seed "$seed"
  fi
  # Screen output on: LIGGGHTS 3.8 crashes reading an STL mesh without a screen.
  (cd "$d" && liggghts -in in.tamp -log log.liggghts > screen.txt)
  "$tamp" import-liggghts-dump "$d/dump.liggghts" --out "$d/measured" --die-stroke "$d/stroke.json" > /dev/null
  python3 "$here/../../die_replay_rows.py" "$d" "$seed" log.liggghts >> "$rows"
  rm -f "$d/dump.liggghts" "$d/measured/trajectory.csv" "$d/screen.txt"
done
mv "$rows" "$out/results.csv"
cat "$out/results.csv"
