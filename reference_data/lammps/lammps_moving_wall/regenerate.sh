#!/usr/bin/env bash
# Re-run LAMMPS for this case: regenerate.sh [OUTDIR] (default: here, i.e. re-record).
exec "$(dirname "$0")/../run_exported.sh" lammps_moving_wall "$@"
