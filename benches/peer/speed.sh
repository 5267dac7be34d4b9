#!/usr/bin/env bash
# Speed against the peer: the same scene in tamp and in LIGGGHTS 3.8, single core, same
# dt and step count, the deck written by `tamp export-liggghts`. Prints each code's wall
# time for the run and particle-steps per second.
# usage: benches/peer/speed.sh [SCENE]   (default: poured_bed_4000.scene.json beside this)
# Needs `liggghts` on PATH and a release build (cargo build --release).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$here/../..
scene=${1:-$here/poured_bed_4000.scene.json}
tamp=$root/target/release/tamp
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$tamp" export-liggghts "$scene" --out "$work/deck" > "$work/export.txt"
read -r n steps < <(sed -E 's/^exported ([0-9]+) particles, ([0-9]+) steps.*/\1 \2/' "$work/export.txt")
(cd "$work/deck" && liggghts -in in.tamp -log log.liggghts -screen none)
lig=$(sed -nE 's/^Loop time of ([0-9.e+-]+) on 1 procs.*/\1/p' "$work/deck/log.liggghts")
start=$(date +%s.%N)
"$tamp" run "$scene" --out "$work/tamp" --quiet > /dev/null
end=$(date +%s.%N)
mine=$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')
printf 'particles %s, steps %s\n' "$n" "$steps"
awk -v n="$n" -v s="$steps" -v l="$lig" -v t="$mine" 'BEGIN {
  printf "LIGGGHTS 3.8  %8.2f s  %.3e particle-steps/s  (its \"Loop time\")\n", l, n * s / l
  printf "tamp          %8.2f s  %.3e particle-steps/s  (whole tamp run, outputs included)\n", t, n * s / t
  printf "tamp speed / LIGGGHTS speed: %.2f\n", l / t
}'
