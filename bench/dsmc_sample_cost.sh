#!/usr/bin/env bash
# Cost per sample of the acoustic DSMC (docs/scaling.md, "A DSMC run too large for one machine"):
#  1. user CPU per sample per collision step: cases/seed002_baseline.toml grown by a factor S in the
#     cross-section (length_y = length_z = 0.01 m x sqrt(S), cells_y = cells_z = sqrt(S), samples x S:
#     same weights, same samples per cell), one thread, run to T1 and to T2; the difference of the two
#     runs removes start-up and output: (U(T2) - U(T1)) / (samples x steps between T1 and T2);
#  2. peak resident memory of the same runs (bytes per sample from the slope between two sizes);
#  3. checkpoint.bin bytes per sample (--checkpoint);
#  4. callgrind instructions per sample per step, split into the engine's phases (motion, binning,
#     collisions, diagnostics), S = 1, from the difference of a T1 and a T2 run (machine independent).
#   bench/dsmc_sample_cost.sh [AGGLO] [OUT_DIR]
#   SCALES="1 9 100" (square numbers), T1=0.005, T2=0.025 (shipped step 5e-5 s: 100 and 500 steps),
#   CALLGRIND=0 skips part 4 (needs valgrind), CG_T1=0.0025, CG_T2=0.005.
#   BEFORE=REV (a commit, e.g. 7181dfe): part 4 also for agglo built from REV (a detached git worktree
#   in OUT/before_src, built in OUT/before_build with ccache when present; both kept for the next run:
#   `git worktree remove OUT/before_src` when done), printed before/after.
#   BEFORE_AGGLO=PATH: an agglo already built from REV (no rebuild). SCALES= (empty): parts 1-3 skipped.
#   N_SOLID=8243, N_LIQUID=160: samples of the two populations at scale 1 (the case's).
#   SELECTION=binned: every run with --set time.selection=binned (default: the case's, nanbu).
#   SMOKE=1: the smoke test (ctest -L bench): SCALES="1 4", T1=1e-4, T2=2e-4 (2 and 4 steps), N_SOLID=824,
#   N_LIQUID=16 without clones (sampling.min_samples_per_cell = 0); part 4 skipped
#   unless CALLGRIND=1 (a callgrind run costs ~3 s even at 10 steps), BEFORE and BEFORE_AGGLO ignored (no
#   rebuild); the same parsing and printing of parts 1-3.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
AGGLO=${1:-$SRC/build/agglo}
OUT=${2:-$SRC/results/bench_dsmc_sample_cost}
if [ "${SMOKE:-0}" = 1 ]; then
  SCALES=${SCALES-"1 4"} T1=${T1:-1e-4} T2=${T2:-2e-4} CALLGRIND=${CALLGRIND:-0} N_SOLID=${N_SOLID:-824}
  N_LIQUID=${N_LIQUID:-16} smoke="--set sampling.min_samples_per_cell=0"
  [ -z "${BEFORE:-}${BEFORE_AGGLO:-}" ] || echo "smoke: BEFORE and BEFORE_AGGLO ignored (no rebuild of a previous commit)"
  unset BEFORE BEFORE_AGGLO
  [ "$CALLGRIND" = 1 ] || echo "smoke: part 4 (callgrind) skipped"
fi
SCALES=${SCALES-"1 9 100"}
T1=${T1:-0.005}
T2=${T2:-0.025}
CALLGRIND=${CALLGRIND:-1}
CG_T1=${CG_T1:-0.0025}
CG_T2=${CG_T2:-0.005}
N_SOLID=${N_SOLID:-8243}
N_LIQUID=${N_LIQUID:-160}
CASE="$SRC/cases/seed002_baseline.toml"
DT=5e-5  # the case's collision_dt = motion_dt
mkdir -p "$OUT"
export OMP_NUM_THREADS=1

isqrt() { local k=0; while (( (k + 1) * (k + 1) <= $1 )); do k=$((k + 1)); done; echo "$k"; }
# Options of a run at scale S to end time T (extra arguments appended). The cross-section 0.01 m x k is
# printed with 17 digits (the double of 0.01 * k exactly).
opts() {
  local s=$1 t=$2
  local k len
  k=$(isqrt "$s")
  len=$(awk -v k="$k" 'BEGIN { printf "%.17g", 0.01 * k }')
  echo "--threads 1 --no-plots --format csv --quiet --overwrite --set time.end=$t \
 --set output.psd_times=[0.0] --set output.snapshot_times=[] --set output.efficiency_interval=$T1 \
 --set domain.length_y=$len --set domain.length_z=$len \
 --set domain.cells_y=$k --set domain.cells_z=$k \
 --set population.0.samples=$((N_SOLID * s)) --set population.1.samples=$((N_LIQUID * s)) ${smoke:-} \
 ${SELECTION:+--set time.selection=$SELECTION}"
}

if [ -n "$SCALES" ]; then
table="$OUT/sample_cost.tsv"
printf 'scale\tsamples\tcells\tT_s\twall_s\tuser_s\tpeak_rss_kB\n' > "$table"
for s in $SCALES; do
  for t in "$T1" "$T2"; do
    dir="$OUT/s${s}_t${t}"
    # shellcheck disable=SC2046
    /usr/bin/time -f "%e %U %M" -o "$dir.time" "$AGGLO" acoustic "$CASE" --out "$dir" $(opts "$s" "$t") > /dev/null
    read -r wall user rss < "$dir.time"
    n=$(/usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(d['samples'])" "$dir/summary.json")
    k=$(isqrt "$s")
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$s" "$n" "$((100 * k * k))" "$t" "$wall" "$user" "$rss" >> "$table"
  done
done
column -t "$table"
/usr/bin/python3 - "$table" "$T1" "$T2" "$DT" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
t1, t2, dt = (float(x) for x in sys.argv[2:5])
steps = round((t2 - t1) / dt)
by = {}
for r in rows:
    by.setdefault(r["scale"], {})[float(r["T_s"])] = r
prev = None
for s, d in by.items():
    a, b = d[t1], d[t2]
    n = int(b["samples"])
    ns = (float(b["user_s"]) - float(a["user_s"])) / (n * steps) * 1e9
    nw = (float(b["wall_s"]) - float(a["wall_s"])) / (n * steps) * 1e9
    print(f"scale {s}: {n} samples in {b['cells']} cells: {ns:.0f} ns user CPU ({nw:.0f} ns wall) per sample per step "
          f"over {steps} steps; peak RSS {int(b['peak_rss_kB']) / 1024:.1f} MiB")
    if prev:
        dn = n - prev[0]
        db = (int(b["peak_rss_kB"]) - prev[1]) * 1024
        print(f"  resident bytes per sample (slope from the previous size): {db / dn:.0f}")
    prev = (n, int(b["peak_rss_kB"]))
EOF

# 3. Checkpoint bytes per sample (scale 1 and the second scale).
for s in $(echo "$SCALES" | cut -d' ' -f1-2); do
  dir="$OUT/ckpt_s$s"
  # shellcheck disable=SC2046
  "$AGGLO" acoustic "$CASE" --out "$dir" $(opts "$s" "$T1") --checkpoint "$T1" > /dev/null
  n=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['samples'])" "$dir/summary.json")
  bytes=$(stat -c %s "$dir/checkpoint.bin")
  echo "checkpoint scale $s: $bytes bytes for $n samples = $(awk -v b="$bytes" -v n="$n" 'BEGIN { printf "%.1f", b / n }') bytes per sample"
done
fi

# 4. Instructions per sample per step by phase (callgrind, scale 1, one thread), for AGGLO and, with
# BEFORE, for agglo built from that commit.
[ "$CALLGRIND" = 1 ] || exit 0
callgrind_runs() {  # callgrind_runs AGGLO DIR
  local a=$1 d=$2 t
  mkdir -p "$d"
  for t in "$CG_T1" "$CG_T2"; do
    # shellcheck disable=SC2046
    valgrind --tool=callgrind --callgrind-out-file="$d/callgrind_$t.out" "$a" acoustic "$CASE" \
      --out "$d/cg_$t" $(opts 1 "$t") > /dev/null 2> "$d/callgrind_$t.log"
    callgrind_annotate --inclusive=yes --threshold=100 "$d/callgrind_$t.out" > "$d/callgrind_$t.txt" 2> /dev/null
  done
}
dirs=("$OUT")
labels=("after ($(git -C "$SRC" rev-parse --short HEAD 2>/dev/null || echo this build))")
if [ -n "${BEFORE:-}" ]; then
  bsrc="$OUT/before_src" bbuild="$OUT/before_build"
  rev=$(git -C "$SRC" rev-parse --short "$BEFORE")
  if [ -n "${BEFORE_AGGLO:-}" ]; then
    mkdir -p "$bbuild" && ln -sf "$(realpath "$BEFORE_AGGLO")" "$bbuild/agglo" && echo "$rev" > "$bbuild/rev"
  fi
  if [ ! -x "$bbuild/agglo" ] || [ "$(cat "$bbuild/rev" 2>/dev/null)" != "$rev" ]; then
    git -C "$SRC" worktree remove --force "$bsrc" 2> /dev/null || rm -rf "$bsrc"
    git -C "$SRC" worktree add --detach "$bsrc" "$rev" > /dev/null
    launcher=()
    command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    cmake -S "$bsrc" -B "$bbuild" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=/usr/bin/python3 \
      "${launcher[@]}" > "$OUT/before_cmake.log"
    cmake --build "$bbuild" --target agglo > "$OUT/before_build.log"
    echo "$rev" > "$bbuild/rev"
  fi
  callgrind_runs "$bbuild/agglo" "$OUT/before"
  dirs=("$OUT/before" "$OUT")
  labels=("before ($rev)" "${labels[0]}")
fi
callgrind_runs "$AGGLO" "$OUT"
/usr/bin/python3 - "$SRC/bench" "$CG_T1" "$CG_T2" "$DT" "${#dirs[@]}" "${dirs[@]}" "${labels[@]}" <<'EOF'
import json, sys
sys.path.insert(0, sys.argv.pop(1))
from callgrind_threads import parse_annotate
a1, a2, dt, k = sys.argv[1], sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
dirs, labels = sys.argv[5:5 + k], sys.argv[5 + k:5 + 2 * k]
phases = [  # (label, function name prefix in callgrind_annotate's inclusive listing; None: the total)
    ("whole program", None),
    ("motion (Motion::advance)", "agglo::acoustics::Motion::advance("),
    ("state check (Engine::state_ok)", "agglo::acoustics::Engine::state_ok("),
    ("cell index (Engine::compute_cells)", "agglo::acoustics::Engine::compute_cells("),
    ("counting sort by cell (Engine::sort_range; sort_cells before h50)",
     "agglo::acoustics::Engine::sort_range(|agglo::acoustics::Engine::sort_cells("),
    ("collisions (Engine::collide_pass)", "agglo::acoustics::Engine::collide_pass("),
    ("output rows (Observer::observe)", "agglo::acoustics::(anonymous namespace)::Observer::observe("),
]
def load(out, t):
    with open(f"{out}/callgrind_{t}.txt") as f:
        return parse_annotate(f)
def get(inc, keys):  # largest inclusive count of the function (its OpenMP and AVX2 clones are inside it),
    return sum(max([v for k, v in inc.items() if k.startswith(key)] or [0]) for key in keys.split("|"))  # summed over |-alternatives
steps = round((float(a2) - float(a1)) / dt)
cols = []
for out in dirs:
    (ta, ia), (tb, ib) = load(out, a1), load(out, a2)
    n = json.load(open(f"{out}/cg_{a2}/summary.json"))["samples"]
    cols.append([((tb - ta) if key is None else (get(ib, key) - get(ia, key))) / (n * steps) for _, key in phases])
print(f"callgrind, {n} samples, steps {round(float(a1) / dt)} -> {round(float(a2) / dt)}: "
      "instructions per sample per step (inclusive)")
w = max(len(p[0]) for p in phases) + 2
print(" " * w + "".join(f"{l:>22}" for l in labels) + ("   before/after" if k == 2 else ""))
for r, (label, _) in enumerate(phases):
    vals = "".join(f"{c[r]:>22.0f}" for c in cols)
    ratio = f"   {cols[0][r] / cols[1][r]:.2f}x" if k == 2 and cols[1][r] > 0 else ""
    print(f"  {label:<{w - 2}}{vals}{ratio}")
EOF
