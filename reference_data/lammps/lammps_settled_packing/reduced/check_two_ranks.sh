#!/usr/bin/env bash
# The reduced deck, seed 1, on 2 MPI ranks must land within the 1-rank seed spread
# (results.csv): for each measure |x_2 - mean_1| <= 3 s_1 sqrt(1 + 1/5), three
# standard deviations of a new run about the mean of five (a prediction interval).
# A 2-rank run is not the 1-rank run to round-off: the ranks sum a sphere's forces in
# another order, and the pile is chaotic, so it is one more sample of the same bed.
# usage: check_two_ranks.sh OUTDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
row=$("$here/run.sh" 1 "$1" 2)
echo "2 ranks, seed 1: $row"
awk -F, -v row="$row" 'NR > 1 { for (k = 2; k <= 4; k++) { x[k, NR] = $k; s[k] += $k }; n++ }
  END {
    split(row, r, ","); bad = 0
    split("seed,packing_fraction,coordination_number,bottom_wall_force_over_weight", name, ",")
    for (k = 2; k <= 4; k++) {
      m = s[k] / n; v = 0
      for (i = 2; i <= n + 1; i++) v += (x[k, i] - m) ^ 2
      sd = sqrt(v / (n - 1)); tol = 3 * sd * sqrt(1 + 1 / n)
      ok = ((r[k] - m) ^ 2 <= tol ^ 2)
      printf "%s: 2 ranks %.6g, 1 rank %.6g +- %.2g (sd over %d seeds), |difference| %.2g, tolerance %.2g: %s\n",
        name[k], r[k], m, sd, n, (r[k] > m ? r[k] - m : m - r[k]), tol, (ok ? "ok" : "OUTSIDE")
      if (!ok) bad = 1
    }
    exit bad
  }' "$here/results.csv"
