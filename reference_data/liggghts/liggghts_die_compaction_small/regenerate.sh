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
  python3 - "$d" "$seed" >> "$rows" <<'PY'
import json, math, sys
d, seed = sys.argv[1], sys.argv[2]
s = json.load(open(f"{d}/stroke.json"))
st, area = s["stroke"], math.pi * (0.5 * s["die_diameter"]) ** 2
n = st["steps_per_record"]
# Thermo rows: step time f_punch[3] f_floor[3] f_punch[9]; each run prints its
# first and last step. A run's first row repeats the previous run's last step with
# the mesh forces counted twice (LIGGGHTS 3.8 adds the setup's force to the
# step's), so the first row of a step is kept: the end of the run.
forces, head = {}, False
for line in open(f"{d}/log.liggghts"):
    w = line.split()
    if w[:2] == ["Step", "Time"]:
        head = True
        continue
    if head and w and w[0].isdigit() and len(w) == 5:
        forces.setdefault(int(w[0]), (float(w[1]), float(w[2]), float(w[3])))
    else:
        head = False
die = [l.strip().split(",") for l in open(f"{d}/measured/die.csv")][1:]
heights = [st["h0"]] + st["heights"]
pressures = [0.0] + st["pressures"]
for k, row in enumerate(die):
    _, fp, ff = forces[k * n]
    print(f"{seed},{k},{k * st['interval']!r},{heights[k]!r},{st['h0']!r},{st['dt']!r},{n},{pressures[k]!r},"
          f"{fp / area!r},{-ff / area!r},{row[3]},{row[4]}")
PY
  rm -f "$d/dump.liggghts" "$d/particles.data" "$d/measured/trajectory.csv" "$d/screen.txt"
done
mv "$rows" "$out/results.csv"
cat "$out/results.csv"
