#!/bin/sh
# tamp itself behind the adapter contract (docs/engines.md): `tamp run` on the resolved
# scene writes trajectory.csv into OUT_DIR as the scene's output block asks. Through
# this script the suite checks its own contract: every case that runs on every engine
# must give the same status here as on the in-process tamp engine.
#   tamp verify --engine command:examples/adapters/tamp_run.sh
# $TAMP names the tamp executable (default: tamp on PATH).
exec "${TAMP:-tamp}" run "$1" --out "$2" --quiet
