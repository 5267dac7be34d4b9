#!/usr/bin/env bash
# Record (or re-run) a cross-check case whose LIGGGHTS deck tamp exports from the
# case's own scene: export, run LIGGGHTS, convert the dump to tamp's run layout.
# usage: reference_data/liggghts/run_exported.sh CASE [OUTDIR]
#   OUTDIR defaults to reference_data/liggghts/CASE (re-record); `tamp crosscheck
#   --live` passes a scratch directory. $TAMP is the tamp executable (default: tamp
#   on PATH; crosscheck sets it to itself).
# Writes OUTDIR/deck/ (in.tamp, particles.data, meshes, log.liggghts, final.liggghts),
# OUTDIR/trajectory.csv and OUTDIR/quantities.csv; the per-step dump is deleted
# once converted.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
case_name=$1
out=$(mkdir -p "${2:-$here/$case_name}" && cd "${2:-$here/$case_name}" && pwd)
tamp=${TAMP:-tamp}
scene=$here/../../verification/$case_name.scene.json
rm -rf "$out/deck"
"$tamp" export-liggghts "$scene" --out "$out/deck"
(cd "$out/deck" && liggghts -in in.tamp -log log.liggghts -screen none)
"$tamp" import-liggghts-dump "$out/deck/dump.liggghts" --out "$out"
rm -f "$out/deck/dump.liggghts"
