#!/usr/bin/env bash
# Cost of cases/charged_aggregate_grounded_wall.toml (issue 25: a charged 200-primary aggregate hitting a
# grounded wall, kappa_p = 2.5, 1 ms of impact, <= 30 min on 2 cores): runs `agglo collide` once under
# /usr/bin/time and prints user CPU, wall, DEM steps, electrostatic solves (and solves per step), the
# seconds inside the solves, and the errors of the held forces measured at the solves (result.json
# electrostatic_hold_error: count, largest, mean relative error; docs/electrostatics.md, coupling).
# AFTER (default 1e-3 s, the case's time.after_contact) shortens the run for a measurement; the script then
# also prints the user CPU scaled linearly to the simulated time of the full case (1 ms after the first
# contact; an extrapolation, not a measurement: the impact's later phases may solve more or less often).
#   bench/charged_aggregate_wall.sh [AGGLO] [OUT_DIR] [--set key=value ...]
#   AFTER=5e-5 THREADS=2 (default 2) NICE=5 (default 0)
#   SMOKE=1: the smoke test (ctest -L bench): AFTER=2e-6, one thread, kappa_p = 1 (the exact point-charge
#   path instead of the spectral solves, 0.1 s of CPU); the same run, hold-error statistics and report.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
AGGLO=${1:-$SRC/build/agglo}
shift $(( $# > 0 ? 1 : 0 ))
OUT=${1:-$SRC/results/bench_charged_aggregate_wall}
shift $(( $# > 0 ? 1 : 0 ))
SMOKE_SET=()
if [ "${SMOKE:-0}" = 1 ]; then
  AFTER=${AFTER:-2e-6}; THREADS=${THREADS:-1}; SMOKE_SET=(--set agglomerate.permittivity=1.0)
fi
AFTER=${AFTER:-1e-3}
THREADS=${THREADS:-2}
NICE=${NICE:-0}
mkdir -p "$OUT"
OMP_NUM_THREADS=$THREADS /usr/bin/time -f "%e %U %S" -o "$OUT/time.txt" \
  nice -n "$NICE" "$AGGLO" -q collide "$SRC/cases/charged_aggregate_grounded_wall.toml" --threads "$THREADS" \
  --set time.after_contact="$AFTER" --no-plots --format csv --overwrite --out "$OUT/run" "${SMOKE_SET[@]}" "$@" > /dev/null
read -r wall user sys < "$OUT/time.txt"
/usr/bin/python3 - "$OUT/run/result.json" "$wall" "$user" "$sys" "$AFTER" "$THREADS" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
wall, user, system, after, threads = map(float, sys.argv[2:])
h = r.get("electrostatic_hold_error", {})
steps, solves = r["steps"], r["electrostatic_solves"]
print(f"threads {threads:.0f}, after_contact {after:g} s, simulated {r['t_end_s']:.4g} s (first contact at {r['t_first_contact_s']:.3g} s)")
print(f"user CPU {user:.1f} s, system {system:.1f} s, wall {wall:.1f} s")
print(f"DEM steps {steps}, dt {r['dt_s']:.4g} s, electrostatic solves {solves} ({solves / steps:.3f} per step), "
      f"{r['electrostatic_seconds']:.1f} s of wall inside them")
if h:
    print(f"held-force error at the {h['solves_measured']} measured solves: largest {h['max_relative']:.3g}, "
          f"mean {h['mean_relative']:.3g} (relative to the largest force); final motion threshold {h['final_update_fraction']:.3g}")
print(f"outcome: broken {r['broken']}, undecided {r['undecided']}, wall contacts at the end {r.get('wall_contacts_at_end', '-')}")
if after < 1e-3:
    scale = (r["t_first_contact_s"] + 1e-3) / r["t_end_s"]
    print(f"extrapolated to 1 ms after contact (user CPU x {scale:.1f}, the ratio of simulated times): "
          f"{user * scale:.0f} s of user CPU ({user * scale / 60:.0f} min; not measured)")
PY
