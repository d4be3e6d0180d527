#!/usr/bin/env bash
# Spectral solver: dense far field against the fast one (electrostatics.far_field = "fmm", issue 25
# item 1; docs/electrostatics.md "Fast far field"), measured in one run of bench_spectral_far_field:
# one cold solve and one set-up + product of a D_f = 1.8 aggregate of N primaries (structure builder,
# kappa_p = 2.5, +-10 uC/m^2, touching primaries 0.01 r apart, L = 47). Prints per N: process CPU
# per solve (user + system of the benchmark process), GMRES iterations, the estimated CPU of one
# product, (solve - setup_and_product) / (iterations + 2), near pairs, M2L count, and the force
# difference fmm vs dense; then the dense/fmm ratios. Timing only (never a test); on a shared machine
# only the ratios of one run mean anything.
#   bench/spectral_far_field.sh [BUILD_DIR]     NS="100 200 400 1000", THREADS=1
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$SRC/build}
NS=${NS:-"100 200 400 1000"}
THREADS=${THREADS:-1}
filter="N:($(echo $NS | tr ' ' '|'))/"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
OMP_NUM_THREADS=$THREADS "$BUILD/bench_spectral_far_field" --benchmark_filter="$filter" \
  --benchmark_format=json > "$out"
/usr/bin/python3 - "$out" <<'PY'
import json, re, sys
runs = json.load(open(sys.argv[1]))["benchmarks"]
rows = {}
for b in runs:
    kind, ff, n = re.match(r"(\w+)/(\w+)_k[\d.]+/N:(\d+)/", b["name"]).groups()
    rows.setdefault(int(n), {}).setdefault(ff, {})[kind] = b
print(f"{'N':>5} {'far':>5} {'solve_cpu_s':>11} {'it':>3} {'product_s':>9} {'near':>7} {'m2l':>6} {'force_vs_dense':>14}")
for n in sorted(rows):
    per = {}
    for ff in ("dense", "fmm"):
        r = rows[n].get(ff, {})
        if "solve" not in r: continue
        s, it = r["solve"]["cpu_time"], int(r["solve"]["gmres_iterations"])
        # a solve applies the product it + 3 times (GMRES: initial and final residual; the final alpha)
        prod = (s - r["product"]["cpu_time"]) / (it + 2) if "product" in r else float("nan")
        per[ff] = (s, prod)
        print(f"{n:>5} {ff:>5} {s:>11.3f} {it:>3} {prod:>9.4f} {r['solve'].get('near_pairs', n*(n-1)//2):>7.0f} "
              f"{r['solve'].get('m2l', 0):>6.0f} {r['solve'].get('force_vs_dense', 0):>14.2e}")
    if len(per) == 2:
        print(f"{n:>5} ratio dense/fmm: solve {per['dense'][0]/per['fmm'][0]:.2f}, product {per['dense'][1]/per['fmm'][1]:.2f}")
PY
