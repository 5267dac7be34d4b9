#!/usr/bin/env bash
# Speed against LAMMPS: LAMMPS's own single-core granular benchmark, the chute of its
# bench/in.chute (32 000 spheres, gran/hooke/history, a frozen rough base, 26°), run in
# LAMMPS and in tamp from the same start state, single core, same dt and steps, with the
# same physics (tamp's scene is gran/hooke/history term for term: chute_bed.py).
# Prints each code's CPU time (user + sys of the whole process, less sensitive than wall
# time to a busy machine), particle-steps per CPU second, and the same statistics of
# both final states.
# usage: benches/peer/chute.sh [STEPS]   (default 10000 steps of 1e-4)
#   CHUTE_STARTS=K    run K starts, the first as built and the others with every flowing
#                     velocity perturbed by 1e-12 (chute_bed.py bench --perturb), in both
#                     codes, and print the final-state statistics' mean and spread over
#                     them for each code (default 1)
#   LMP, PYTHON       the LAMMPS binary and a python3 with numpy (default: lmp, python3
#                     on PATH; .ci/install-lammps provides both in .peers/bin)
#   CHUTE_DATA=FILE   time LAMMPS's own bench/data.chute (or any such data file) instead
#                     of the bed made by chute_bed.py
#   CHUTE_BED=DIR     where the warmed-up bed is kept (default target/chute-bed); the
#                     warm-up runs once (4–5 CPU minutes), delete DIR to redo it
#   CHUTE_WARMUP=N    warm-up steps (default 80000, 8 time units)
# Needs LAMMPS with the GRANULAR package, python3 with numpy, and a release build
# (cargo build --release). Installs nothing.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
steps=${1:-10000}
gen=$here/chute_bed.py
tamp=${CARGO_TARGET_DIR:-$root/target}/release/tamp
bed=${CHUTE_BED:-${CARGO_TARGET_DIR:-$root/target}/chute-bed}
warmup=${CHUTE_WARMUP:-80000}
starts=${CHUTE_STARTS:-1}
lmp=${LMP:-lmp}
py=${PYTHON:-python3}

if ! command -v "$lmp" > /dev/null; then
  echo "chute.sh: no LAMMPS binary '$lmp' (set LMP; .ci/install-lammps puts one in .peers/bin)" >&2
  exit 1
fi
if ! "$lmp" -h 2> /dev/null | grep 'gran/hooke/history' > /dev/null; then
  echo "chute.sh: this lmp has no pair style gran/hooke/history (GRANULAR package)" >&2
  exit 1
fi
"$py" -c 'import numpy' 2> /dev/null || { echo "chute.sh: needs python3 with numpy (set PYTHON)" >&2; exit 1; }
[ -x "$tamp" ] || { echo "chute.sh: no $tamp; run cargo build --release" >&2; exit 1; }

# CPU seconds (user + sys) of a command and everything it waited for.
cpu() {
  local out=$1
  shift
  "$py" - "$out" "$@" << 'EOF'
import resource, subprocess, sys
subprocess.run(sys.argv[2:], check=True, stdout=subprocess.DEVNULL)
r = resource.getrusage(resource.RUSAGE_CHILDREN)
open(sys.argv[1], "w").write(f"{r.ru_utime + r.ru_stime:.3f}\n")
EOF
}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ -n "${CHUTE_DATA:-}" ]; then
  from=(--data "$CHUTE_DATA")
  source="LAMMPS data file $CHUTE_DATA"
else
  if [ ! -f "$bed/warm/trajectory.csv" ]; then
    mkdir -p "$bed"
    echo "building the bed in $bed ($warmup warm-up steps in tamp) ..." >&2
    "$py" "$gen" deposit "$bed/deposit.scene.json"
    "$tamp" run "$bed/deposit.scene.json" --out "$bed/deposit" --quiet > /dev/null
    "$py" "$gen" warmup "$bed/deposit/trajectory.csv" "$bed/warm.scene.json" --steps "$warmup"
    "$tamp" run "$bed/warm.scene.json" --out "$bed/warm" --quiet > /dev/null
  fi
  from=(--trajectory "$bed/warm/trajectory.csv" --scene "$bed/warm.scene.json")
  source="chute_bed.py bed after $(sed -nE 's/.*"steps": ?([0-9]+).*/\1/p' "$bed/warm/summary.json" | head -1) warm-up steps"
fi

n=32000
printf 'chute: %s particles, %s steps of 1e-4, start state: %s\n' "$n" "$steps" "$source"
for ((k = 0; k < starts; k++)); do
  run=$work/start$k
  "$py" "$gen" bench "${from[@]}" "$run" --steps "$steps" --perturb "$k" > /dev/null
  (cd "$run/lammps" && export OMP_NUM_THREADS=1 && cpu ../lammps.cpu "$lmp" -in in.chute -log log.lammps -screen none)
  cpu "$run/tamp.cpu" "$tamp" run "$run/chute.scene.json" --out "$run/tamp" --quiet

  log=$run/lammps/log.lammps
  loop=$(sed -nE 's/^Loop time of ([0-9.e+-]+) on 1 procs.*/\1/p' "$log")
  use=$(sed -nE 's/^([0-9.]+)% CPU use.*/\1/p' "$log")
  version=$(sed -n '1s/^LAMMPS (\(.*\))$/\1/p' "$log")
  lmp_cpu=$(cat "$run/lammps.cpu")
  tamp_cpu=$(cat "$run/tamp.cpu")
  [ "$k" -eq 0 ] || printf '\nstart %s (flowing velocities perturbed by 1e-12, seed %s)\n' "$k" "$k"
  printf 'LAMMPS %s (1 MPI process, 1 OpenMP thread)\n' "$version"
  awk -v n="$n" -v s="$steps" -v l="$lmp_cpu" -v t="$tamp_cpu" -v loop="$loop" -v use="$use" 'BEGIN {
    printf "%-8s %10s %28s\n", "code", "CPU time", "particle-steps per CPU s"
    printf "%-8s %8.2f s %28.3e   (its Loop time %.2f s wall at %s%% CPU)\n", "LAMMPS", l, n * s / l, loop, use
    printf "%-8s %8.2f s %28.3e   (whole run: build and outputs included)\n", "tamp", t, n * s / t
    printf "tamp speed / LAMMPS speed: %.2f\n", l / t
  }'
  "$py" "$gen" measure --lammps "$run/lammps/final.dump" > "$run/lammps.json"
  "$py" "$gen" measure --tamp "$run/tamp/trajectory.csv" --scene "$run/chute.scene.json" > "$run/tamp.json"
  echo "final state (same measure for both; contacts exclude base-base pairs):"
  printf '  LAMMPS %s\n' "$(cat "$run/lammps.json")"
  printf '  tamp   %s\n' "$(cat "$run/tamp.json")"
done
if [ "$starts" -gt 1 ]; then
  echo
  echo "final-state statistics over the $starts starts, mean ± standard deviation:"
  "$py" - "$work" "$starts" << 'EOF'
import json, statistics, sys
work, starts = sys.argv[1], int(sys.argv[2])
runs = {code: [json.load(open(f"{work}/start{k}/{code}.json")) for k in range(starts)]
        for code in ("lammps", "tamp")}
for key in runs["tamp"][0]:
    line = f"  {key:22s}"
    for code in ("lammps", "tamp"):
        values = [r[key] for r in runs[code]]
        line += f"  {code} {statistics.mean(values):.6g} ± {statistics.stdev(values):.3g}"
    print(line)
EOF
fi
