#!/usr/bin/env bash
# Record (or re-run) the LAMMPS side of nial_die_compaction_dense: the replay of tamp's MDR pressing of
# verification/nial_die_compaction_dense.scene.json to 600 MPa, seed 1 (../die_replay.sh says how).
# usage: regenerate.sh [OUTDIR]   (default: this directory, i.e. re-record)
#   $TAMP and $LMP as ../die_replay.sh takes them. A re-record presses in tamp first (about an
#   hour of one core), then LAMMPS replays the stroke; a live run (OUTDIR) replays the recorded deck.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
scene=${SCENE:-$here/../../../verification/nial_die_compaction_dense.scene.json}
export SEEDS=1
exec bash "$here/../die_replay.sh" "$here" "$scene" "$@"
