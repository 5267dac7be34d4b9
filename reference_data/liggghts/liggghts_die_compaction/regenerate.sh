#!/usr/bin/env bash
# Record (or re-run) the LIGGGHTS side of liggghts_die_compaction (full tier): the
# 1751-particle specimen of nial_die_compaction pressed frictionless (pressing mu0)
# and with mu = 0.05 between particles (pressing mu0.05), each as
# liggghts_die_compaction_small does it: tamp fills, flattens and presses the
# specimen and exports the pressing as a deck that replays tamp's punch stroke
# (tamp export-liggghts on the pressing's die-compaction file); LIGGGHTS runs it;
# the particles' force on punch and floor at every record come from LIGGGHTS's
# thermo output, the densities from tamp's measure of every record's frame
# (import-liggghts-dump --die-stroke). One row per pressing, seed and record.
# usage: regenerate.sh [OUTDIR]   (default: this directory, i.e. re-record)
#   $TAMP is the tamp executable (default: tamp on PATH; crosscheck sets it).
#   $SEEDS the seeds (default: 1 2 3, the recorded ones). $PRESSINGS the pressings (default: both).
# With an OUTDIR (crosscheck --live), a pressing and seed whose deck is recorded
# here runs that deck as it is (the export would press in tamp again only to write
# the same files; the case checks they are not stale). Others are exported.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$(mkdir -p "${1:-$here}" && cd "${1:-$here}" && pwd)
tamp=${TAMP:-tamp}
verification=$here/../../../verification
rows=$out/.results.csv.tmp
echo "pressing,seed,record,time,height,h0,dt,steps_per_record,tamp_pressure,punch_pressure,floor_pressure,density_specimen,density_rve" > "$rows"
for pressing in ${PRESSINGS:-mu0 mu0.05}; do
  case $pressing in
    mu0) scene=$verification/liggghts_die_compaction.scene.json ;;
    mu0.05) scene=$verification/liggghts_die_compaction_mu0.05.scene.json ;;
    *) echo "unknown pressing $pressing" >&2; exit 2 ;;
  esac
  # Each pressing is recorded as liggghts_die_compaction_small records its one.
  SCENE=$scene RECORDED=$here/$pressing SEEDS="${SEEDS:-1 2 3}" TAMP=$tamp \
    "$here/../liggghts_die_compaction_small/regenerate.sh" "$out/$pressing" > /dev/null
  tail -n +2 "$out/$pressing/results.csv" | sed "s/^/$pressing,/" >> "$rows"
  rm "$out/$pressing/results.csv"
done
mv "$rows" "$out/results.csv"
cat "$out/results.csv"
