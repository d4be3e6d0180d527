#!/usr/bin/env bash
# Spectral solver: dense far field against the fast one (electrostatics.far_field = "fmm", issue 25
# item 1; docs/electrostatics.md "Fast far field"), and the fast one with its near pairs' stored rotation
# blocks ("fmm_stored", the twin of the shared quarter turns; kappa_p = 2.5 only), measured in one run of
# bench_spectral_far_field:
# a D_f = 1.8 aggregate of N primaries (structure builder, kappa_p = 2.5, +-10 uC/m^2, touching
# primaries 0.01 r apart, L = 47). Prints per N and far field the process CPU (user + system) of one cold
# solve, its GMRES iterations, the CPU of one product ((6 products - 1 product) / 5 after one set-up),
# the set-up (1 product - one product), near pairs, M2L count, the force difference fmm vs dense, and
# the dense/fmm and fmm_stored/fmm ratios; each time is the least of REPS repetitions. Timing only (never a test); on a
# shared machine only the ratios of one run mean anything.
#   bench/spectral_far_field.sh [BUILD_DIR]     NS="100 200 400 1000", THREADS=1, REPS=3, ONLY=regex
# ONLY selects benchmarks by name (e.g. ONLY='solve/fmm' for the fast far field alone; N = 2000 and 3000
# are registered for fmm only).
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$SRC/build}
NS=${NS:-"100 200 400 1000"}
THREADS=${THREADS:-1}
REPS=${REPS:-3}
filter="${ONLY:-}.*N:($(echo $NS | tr ' ' '|'))/"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
OMP_NUM_THREADS=$THREADS "$BUILD/bench_spectral_far_field" --benchmark_filter="$filter" \
  --benchmark_repetitions="$REPS" --benchmark_format=json > "$out"
/usr/bin/python3 - "$out" <<'PY'
import json, re, sys
best, counters = {}, {}
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    if b.get("run_type") != "iteration":
        continue
    kind, ff, kap, n, k = re.match(r"(\w+)/(\w+)_k([\d.]+)/N:(\d+)/(?:products:(\d+)/)?", b["name"]).groups()
    key = (kap, int(n), ff, kind, int(k or 0))
    best[key] = min(best.get(key, float("inf")), b["cpu_time"])
    counters[key] = b
print(f"{'kappa':>5} {'N':>5} {'far':>10} {'solve_s':>8} {'it':>3} {'product_s':>9} {'setup_s':>8} {'near':>7} {'m2l':>6} {'F_vs_dense':>10}")
for kap, n in sorted({k[:2] for k in best}, key=lambda t: (float(t[0]), t[1])):
    row = {}
    for ff in ("dense", "fmm_stored", "fmm"):
        if (kap, n, ff, "solve", 0) not in best:
            continue
        s, c = best[(kap, n, ff, "solve", 0)], counters[(kap, n, ff, "solve", 0)]
        p1 = best.get((kap, n, ff, "product", 1), float("nan"))
        p6 = best.get((kap, n, ff, "product", 6), float("nan"))
        prod = (p6 - p1) / 5
        row[ff] = (s, prod)
        print(f"{kap:>5} {n:>5} {ff:>10} {s:>8.3f} {int(c['gmres_iterations']):>3} {prod:>9.4f} {p1 - prod:>8.3f} "
              f"{c.get('near_pairs', n * (n - 1) // 2):>7.0f} {c.get('m2l', 0):>6.0f} {c.get('force_vs_dense', 0):>10.2e}")
    for ref in ("dense", "fmm_stored"):
        if ref in row and "fmm" in row:
            print(f"{kap:>5} {n:>5} {ref}/fmm: solve {row[ref][0] / row['fmm'][0]:.2f}x, product {row[ref][1] / row['fmm'][1]:.2f}x")
PY
