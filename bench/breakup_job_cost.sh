#!/usr/bin/env bash
# Cost spread of the jobs of a break-up curve (docs/scaling.md, cost model): single impacts of a case
# at a few speeds of its break-up grid, one thread each, one after the other, each under /usr/bin/time.
# Prints per speed: broken or not, DEM steps, simulated time, wall and user CPU seconds; then the
# ratio slowest/fastest (user CPU and steps). Steps are machine independent; seconds are not.
#   bench/breakup_job_cost.sh [AGGLO] [OUT_DIR] [CASE]
#   SPEEDS="0.02 0.125 ..." (default: the 12 speeds of the vcrit scan grid 0.02..0.6 m/s, 3-4 digits)
#   OFFSET=0.05 (projectile.offset_radii of every run)
#   SMOKE=1: the smoke test (ctest -L bench): SPEEDS="0.3 0.6", each run cut to 2 us after contact from a
#   0.02 r gap (no relaxation, no extensions), electrostatics.target_accuracy = 0.1 and update_fraction =
#   0.2; the same table and ratios.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
AGGLO=${1:-$SRC/build/agglo}
OUT=${2:-$SRC/results/bench_breakup_job_cost}
CASE=${3:-$SRC/cases/seed000_charged_square_k2p5.toml}
smoke=()
if [ "${SMOKE:-0}" = 1 ]; then
  SPEEDS=${SPEEDS:-"0.3 0.6"}
  smoke=(--set projectile.gap_radii=0.02 --set time.after_contact=2e-6 --set time.max_extensions=0 --set time.relax_time=0
         --set electrostatics.target_accuracy=1e-1 --set electrostatics.update_fraction=0.2)
fi
SPEEDS=${SPEEDS:-"0.02 0.0727 0.125 0.178 0.231 0.2836 0.336 0.3891 0.4418 0.4945 0.5473 0.6"}
OFFSET=${OFFSET:-0.05}
mkdir -p "$OUT"
table="$OUT/job_cost.tsv"
printf 'speed_m_per_s\tbroken\tsteps\tt_end_s\twall_s\tuser_s\n' > "$table"
for v in $SPEEDS; do
  dir="$OUT/v_$v"
  OMP_NUM_THREADS=1 /usr/bin/time -f "%e %U" -o "$OUT/time_$v.txt" \
    "$AGGLO" -q collide "$CASE" --speed "$v" --set projectile.offset_radii="$OFFSET" --threads 1 \
    --no-plots --format csv --overwrite --out "$dir" "${smoke[@]}" > /dev/null
  read -r wall user < "$OUT/time_$v.txt"
  /usr/bin/python3 - "$dir/result.json" "$v" "$wall" "$user" >> "$table" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]}\t{str(r['broken']).lower()}\t{r['steps']}\t{r['t_end_s']:.4g}\t{sys.argv[3]}\t{sys.argv[4]}")
EOF
done
column -t "$table"
/usr/bin/python3 - "$table" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
u = [float(r["user_s"]) for r in rows]
s = [int(r["steps"]) for r in rows]
ratio = f"{max(u) / min(u):.1f}x" if min(u) > 0 else "- (a run under 0.01 s)"
print(f"slowest/fastest: user CPU {ratio}, steps {max(s) / min(s):.1f}x; "
      f"sum user {sum(u):.1f} s, mean {sum(u) / len(u):.1f} s, longest {max(u):.1f} s")
EOF
