#!/usr/bin/env bash
# Re-run LIGGGHTS for this case: regenerate.sh [OUTDIR] (default: here, i.e. re-record).
exec "$(dirname "$0")/../run_exported.sh" liggghts_two_sphere_thornton "$@"
