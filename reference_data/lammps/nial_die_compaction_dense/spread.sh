#!/usr/bin/env bash
# The run-to-run spread behind nial_die_compaction_dense's tolerances: LAMMPS replays the
# recorded deck (seed1/) with every initial x moved by k ulps, for each k given (default 1),
# and each quantity the case compares is printed for the recorded and the moved run, with
# their difference. One ulp is another round-off path through the same physics; how far it
# takes LAMMPS from itself is how far two correct codes may part on this specimen.
# The punch passes through the same heights in both runs, so a record's specimen density is
# the recorded one and only the punch pressure (thermo output) is read from the moved run;
# a moved run that stops early (LAMMPS's "F_MDR is NaN") is compared up to where it stopped.
# usage: spread.sh WORKDIR [K ...]   (about 80 min of one core per k; the k run in parallel)
#   $LMP as for regenerate.sh.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$here/../../..
lmp=${LMP:-$root/.peers/bin/lmp}
work=$(mkdir -p "$1" && cd "$1" && pwd)
shift
ks=${*:-1}
one() {
  k=$1 d=$work/ulp$1
  rm -rf "$d" && mkdir -p "$d"
  cp "$here/seed1/in.tamp" "$here/seed1/stroke.json" "$d/"
  python3 - "$here/seed1/particles.data" "$d/particles.data" "$k" <<'PY'
import math, sys
src, dst, k = sys.argv[1], sys.argv[2], int(sys.argv[3])
out, atoms = [], False
for line in open(src):
    w = line.split()
    if line.startswith("Atoms"):
        atoms = True
    elif atoms and len(w) == 7:
        x = float(w[4])
        for _ in range(abs(k)):
            x = math.nextafter(x, math.copysign(math.inf, k))
        w[4] = repr(x)
        line = " ".join(w) + "\n"
    elif atoms and w and len(w) != 7:
        atoms = False
    out.append(line)
open(dst, "w").writelines(out)
PY
  (cd "$d" && "$lmp" -in in.tamp -log log.lammps -screen none -nocite) || echo "k=$k: LAMMPS stopped: $(grep ERROR "$d/log.lammps" || true)"
  rm -f "$d/dump.lammps"
}
for k in $ks; do one "$k" & done
wait
python3 - "$root/reference_data" "$here/results.csv" "$work" $ks <<'PY'
import csv, math, sys, json
sys.path.insert(0, sys.argv[1])
from die_replay_rows import thermo_forces
recorded, work, ks = sys.argv[2], sys.argv[3], sys.argv[4:]
rows = list(csv.DictReader(open(recorded)))
n = int(rows[0]["steps_per_record"])
area = math.pi * (0.5 * json.load(open(f"{work}/ulp{ks[0]}/stroke.json"))["die_diameter"]) ** 2
rec = [(float(r["punch_pressure"]), float(r["density_specimen"])) for r in rows]
def moved(k):
    force = thermo_forces(f"{work}/ulp{k}/log.lammps")
    return [(force[j * n][1] / area, rec[j][1]) for j in range(len(rec)) if j * n in force]
def density_at(c, p):
    for a, b in zip(c, c[1:]):
        if a[0] <= p <= b[0]:
            return a[1] + (p - a[0]) / (b[0] - a[0]) * (b[1] - a[1])
def pressure_at(c, phi):
    for a, b in zip(c, c[1:]):
        if a[1] < phi <= b[1]:
            return a[0] + (phi - a[1]) / (b[1] - a[1]) * (b[0] - a[0])
for k in ks:
    m = moved(k)
    print(f"k={k}: {len(m)} of {len(rec)} records, the last at {m[-1][0] / 1e6:.1f} MPa")
    for p in (100, 300, 500, 530, 600):
        a, b = density_at(rec, p * 1e6), density_at(m, p * 1e6)
        if a is None or b is None:
            print(f"k={k} density at {p} MPa: not reached by both runs")
        else:
            print(f"k={k} density at {p} MPa: recorded {a:.5f}, moved {b:.5f}, difference {b - a:+.4f}")
    # Past the moved run's last record: the punch pressure's relative difference at the
    # same height over the records past 300 MPa (RMS), through the recorded curve's slope.
    rel = [(y[0] - x[0]) / x[0] for x, y in zip(rec, m) if x[0] > 300e6]
    rms = (sum(r * r for r in rel) / len(rel)) ** 0.5
    slope = (rec[-1][1] - rec[-11][1]) / (rec[-1][0] - rec[-11][0])
    print(f"k={k} punch pressure past 300 MPa, {len(rel)} records: RMS relative difference {rms:.4f}; "
          f"at 600 MPa, 3 x RMS x 600 MPa x slope {slope * 1e6:.3e}/MPa = {3 * rms * 600e6 * slope:.4f}")
    a, b = pressure_at(rec, 0.85), pressure_at(m, 0.85)
    print(f"k={k} pressure at density 0.85: recorded {a / 1e6:.1f} MPa, moved {b / 1e6:.1f} MPa, relative difference {b / a - 1:+.4f}")
PY
