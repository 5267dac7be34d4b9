#!/usr/bin/env bash
# The run-to-run spread behind lammps_mdr_tableting's tolerances: the scene with every
# initial x moved by k ulps (k = 0, +-1 ... +-5), run by tamp and, as its exported deck,
# by LAMMPS; prints each quantity's mean and standard deviation in both codes, the
# difference of the means in standard errors, and 3 sqrt(s_tamp^2 + s_lammps^2)/|mean|.
# usage: spread.sh [WORKDIR]   (default: a new temporary directory; about 4 min on 2 cores)
#   $LMP, $TAMP as for regenerate.sh.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$here/../../..
lmp=${LMP:-$root/.peers/bin/lmp}
tamp=${TAMP:-$root/target/release/tamp}
work=$(mkdir -p "${1:-$(mktemp -d)}" && cd "${1:-.}" && pwd)
ks="0 1 -1 2 -2 3 -3 4 -4 5 -5"
for k in $ks; do
  python3 - "$root/verification/lammps_mdr_tableting.scene.json" "$work/scene_$k.json" "$k" <<'PY'
import json, math, sys
scene = json.load(open(sys.argv[1]))
k = int(sys.argv[3])
for p in scene["particles"]:
    for _ in range(abs(k)):
        p["position"][0] = math.nextafter(p["position"][0], math.copysign(math.inf, k))
json.dump(scene, open(sys.argv[2], "w"))
PY
done
one() {
  k=$1
  rm -rf "$work/tamp_$k" "$work/lammps_$k"
  "$tamp" run "$work/scene_$k.json" --out "$work/tamp_$k" --quiet
  "$tamp" export-lammps "$work/scene_$k.json" --out "$work/lammps_$k" > /dev/null
  (cd "$work/lammps_$k" && "$lmp" -in in.tamp -log log.lammps -screen none -nocite)
}
set -- $ks
while [ $# -gt 0 ]; do
  one "$1" &
  if [ $# -gt 1 ]; then one "$2"; fi
  wait
  shift; [ $# -gt 0 ] && shift
done
python3 - "$work" $ks <<'PY'
import csv, math, statistics as st, sys
work, ks = sys.argv[1], sys.argv[2:]
def walls(path):
    d = {}
    for r in csv.DictReader(open(path)):
        d[(int(r["step"]), int(r["wall"]))] = float(r["fz"])
    return d
def radii_tamp(path):
    rows = list(csv.DictReader(open(path)))
    last = max(int(r["step"]) for r in rows)
    return [float(r["radius"]) for r in rows if int(r["step"]) == last]
def radii_lammps(path):
    out, cols = [], None
    for line in open(path):
        if line.startswith("ITEM: ATOMS"):
            cols = line.split()[2:]
        elif cols and line.strip():
            out.append(float(dict(zip(cols, line.split()))["radius"]))
    return out
def quantities(w, radii):
    return {
        "upper_punch_force_full_stroke": w[(12000, 2)],
        "floor_force_full_stroke": w[(12000, 1)] + w[(12000, 4)],
        "die_friction_full_stroke": w[(12000, 3)],
        "upper_punch_force_release": w[(13500, 2)],
        "mean_apparent_radius_end": sum(radii) / len(radii),
    }
t = [quantities(walls(f"{work}/tamp_{k}/walls.csv"), radii_tamp(f"{work}/tamp_{k}/trajectory.csv")) for k in ks]
l = [quantities(walls(f"{work}/lammps_{k}/walls.csv"), radii_lammps(f"{work}/lammps_{k}/final.lammps")) for k in ks]
for name in t[0]:
    a, b = [x[name] for x in t], [x[name] for x in l]
    ma, mb, sa, sb = st.mean(a), st.mean(b), st.stdev(a), st.stdev(b)
    se = math.sqrt(sa**2 / len(a) + sb**2 / len(b))
    print(f"{name}: tamp {ma:.6g} sd {sa:.2g}, lammps {mb:.6g} sd {sb:.2g}, "
          f"means {(ma - mb) / abs(mb):+.2e} apart ({(ma - mb) / se:+.1f} standard errors), "
          f"3 sqrt(sa^2 + sb^2)/|mean| {3 * math.sqrt(sa**2 + sb**2) / abs(mb):.2g}")
PY
