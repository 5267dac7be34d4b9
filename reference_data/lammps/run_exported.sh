#!/usr/bin/env bash
# Record (or re-run) a cross-check case whose LAMMPS deck tamp exports from the
# case's own scene: export, run LAMMPS 22 Jul 2025, convert the dump to tamp's run
# layout (LAMMPS's dump custom has the columns and format of LIGGGHTS's, so
# import-liggghts-dump reads it).
# usage: reference_data/lammps/run_exported.sh CASE [OUTDIR]
#   OUTDIR defaults to reference_data/lammps/CASE (re-record); `tamp crosscheck
#   --live` passes a scratch directory. $TAMP is the tamp executable (default: tamp
#   on PATH; crosscheck sets it to itself), $LMP LAMMPS (default .peers/bin/lmp).
# Writes OUTDIR/deck/ (in.tamp, particles.data, log.lammps, final.lammps),
# OUTDIR/trajectory.csv and OUTDIR/quantities.csv; the per-step dump is deleted
# once converted.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
case_name=$1
out=$(mkdir -p "${2:-$here/$case_name}" && cd "${2:-$here/$case_name}" && pwd)
tamp=${TAMP:-tamp}
lmp=${LMP:-$here/../../.peers/bin/lmp}
scene=$here/../../verification/$case_name.scene.json
rm -rf "$out/deck"
"$tamp" export-lammps "$scene" --out "$out/deck"
(cd "$out/deck" && "$lmp" -in in.tamp -log log.lammps -screen none -nocite)
"$tamp" import-liggghts-dump "$out/deck/dump.lammps" --out "$out"
rm -f "$out/deck/dump.lammps"
