#!/usr/bin/env bash
# Record (or re-run) the LAMMPS side of lammps_die_compaction_small_mdr: the replay of tamp's pressing of
# verification/lammps_die_compaction_small_mdr.scene.json, one seed at a time (../die_replay.sh says how).
# usage: regenerate.sh [OUTDIR]   (default: this directory, i.e. re-record)
#   $TAMP, $LMP and $SEEDS as ../die_replay.sh takes them; SEEDS defaults to the three
#   seeds results.csv records, so that a live re-run gives the same rows.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
scene=${SCENE:-$here/../../../verification/lammps_die_compaction_small_mdr.scene.json}
export SEEDS=${SEEDS:-1 2 3}
exec bash "$here/../die_replay.sh" "$here" "$scene" "$@"
