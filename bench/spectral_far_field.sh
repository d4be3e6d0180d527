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
# Also (issue 25 item 3): "reference", the converged reference of the same aggregate (fast far field at
# target 1e-6) that every later solve of that N and kappa_p is compared with (F_vs_ref: max_i |F_i -
# F_ref,i| / max_i |F_ref,i|), "reference_check" (target 1e-7, against the reference: how converged it
# is), "bem" (BEM+FMM, 100 patches per sphere, GMRES to 1e-2); registered for N = 100 and 1000 (select
# them with ONLY, e.g. ONLY='solve/(reference|fmm|bem)_k2.5'); and the growth exponent of the solve
# between the smallest and the largest N of each far field.
# Issue 25, sixth session: "fmm_pc_<name>" (the right preconditioners of SolverOptions::preconditioner,
# coarse, pair, contact (measuring tools) and contact_low; N = 10, 100, 200, 1000) and "fmm_acc<target>[_tol<GMRES
# tolerance>][_L<fixed degree>][_pcl]" (the accuracy-cost curve at N = 1000 against the reference, _pcl with
# the contact_low preconditioner; e.g.
# ONLY='solve/(reference|fmm|fmm_acc[^/]*)_k(2.5|15)' NS=1000 REPS=1).
#   bench/spectral_far_field.sh [BUILD_DIR]     NS="100 200 400 1000", THREADS=1, REPS=3, ONLY=regex
# ONLY selects benchmarks by name (e.g. ONLY='solve/fmm' for the fast far field alone; N = 2000 and 3000
# are registered for the fmm solves and products and the dense kappa_p = 2.5 solve, so that
# ONLY='solve/(dense|fmm)_k2.5' NS="100 200 400 1000 2000 3000" measures both growth exponents to N = 3000
# in one run).
#   SMOKE=1: the smoke test (ctest -L bench): NS=10 (registered for this), REPS=1, ONLY the solves and
#   products of the dense and the fast far field at kappa_p = 2.5 (the others cost 0.3-3 s each even
#   there); the same parsing, table and ratios (no growth exponent: one N).
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${1:-$SRC/build}
if [ "${SMOKE:-0}" = 1 ]; then
  NS=${NS:-10} REPS=${REPS:-1} ONLY=${ONLY-"(solve|product)/(dense|fmm)_k2.5/"}
fi
NS=${NS:-"100 200 400 1000"}
THREADS=${THREADS:-1}
REPS=${REPS:-3}
filter="${ONLY:-}.*N:($(echo $NS | tr ' ' '|'))/"
out=$(mktemp)
trap 'rm -f "$out"' EXIT
OMP_NUM_THREADS=$THREADS "$BUILD/bench_spectral_far_field" --benchmark_filter="$filter" \
  --benchmark_repetitions="$REPS" --benchmark_format=json > "$out"
/usr/bin/python3 - "$out" <<'PY'
import json, math, re, sys
best, counters = {}, {}
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    if b.get("run_type") != "iteration":
        continue
    kind, ff, kap, n, k = re.match(r"(\w+)/([\w.-]+)_k([\d.]+)/N:(\d+)/(?:products:(\d+)/)?", b["name"]).groups()
    key = (kap, int(n), ff, kind, int(k or 0))
    best[key] = min(best.get(key, float("inf")), b["cpu_time"])
    counters[key] = b
print(f"{'kappa':>5} {'N':>5} {'far':>22} {'solve_s':>8} {'it':>3} {'product_s':>9} {'setup_s':>8} {'near':>7} {'m2l':>6} {'F_vs_dense':>10} {'F_vs_ref':>9}")
def opt(c, key, width):  # a counter the run has, or "-" (no dense or reference run of that N)
    return f"{c[key]:>{width}.2e}" if key in c else f"{'-':>{width}}"
kinds = ("reference", "reference_check", "dense", "fmm_stored", "fmm", "bem")
# then the preconditioner rows (fmm_pc_<name>) and the accuracy-cost rows (fmm_acc<target>[_tol<t>][_L<L>])
kinds += tuple(sorted({k[2] for k in best} - set(kinds)))
for kap, n in sorted({k[:2] for k in best}, key=lambda t: (float(t[0]), t[1])):
    row = {}
    for ff in kinds:
        if (kap, n, ff, "solve", 0) not in best:
            continue
        s, c = best[(kap, n, ff, "solve", 0)], counters[(kap, n, ff, "solve", 0)]
        p1 = best.get((kap, n, ff, "product", 1), float("nan"))
        p6 = best.get((kap, n, ff, "product", 6), float("nan"))
        prod = (p6 - p1) / 5
        row[ff] = (s, prod)
        near = c.get('near_pairs', n * (n - 1) // 2 if ff != "bem" else 0)
        print(f"{kap:>5} {n:>5} {ff:>22} {s:>8.3f} {int(c['gmres_iterations']):>3} {prod:>9.4f} {p1 - prod:>8.3f} "
              f"{near:>7.0f} {c.get('m2l', 0):>6.0f} {opt(c, 'force_vs_dense', 10)} {opt(c, 'force_vs_reference', 9)}")
    for ref in ("dense", "fmm_stored"):
        if ref in row and "fmm" in row:
            print(f"{kap:>5} {n:>5} {ref}/fmm: solve {row[ref][0] / row['fmm'][0]:.2f}x, product {row[ref][1] / row['fmm'][1]:.2f}x")
for kap in sorted({k[0] for k in best}, key=float):
    for ff in kinds:
        ns = sorted(k[1] for k in best if k[0] == kap and k[2] == ff and k[3] == "solve")
        if len(ns) >= 2:
            a, b = best[(kap, ns[0], ff, "solve", 0)], best[(kap, ns[-1], ff, "solve", 0)]
            print(f"kappa {kap} {ff}: solve grows as N^{math.log(b / a) / math.log(ns[-1] / ns[0]):.2f} from N = {ns[0]} to {ns[-1]}")
PY
