#!/usr/bin/env bash
# Re-run LAMMPS for this case: regenerate.sh [OUTDIR] (default: here, i.e. re-record).
exec "$(dirname "$0")/../run_cylinder_wall.sh" "$@"
