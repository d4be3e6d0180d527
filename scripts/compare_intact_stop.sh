#!/usr/bin/env bash
# Tests time.intact_stop against full-length runs (src/agglo/impact/intact.hpp): the vcrit bisection of CASE
# with the early stop of intact runs off and on, run by run: the outcome (broken, undecided, contact) of every
# speed tried must agree, so the bracket and v_crit are the same; prints steps, electrostatic solves and user
# CPU of both. Usage: scripts/compare_intact_stop.sh CASE [OUT] [agglo arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
case_file=$1
out=${2:-results/compare_intact_stop}
shift $(( $# >= 2 ? 2 : 1 ))
A=${AGGLO:-build/agglo}
for mode in off vcrit; do
  /usr/bin/time -f "$mode: %U s user CPU" -o "$out-$mode.time" \
    $A -q --no-plots vcrit "$case_file" --overwrite --out "$out-$mode" --set "time.intact_stop=\"$mode\"" "$@"
  cat "$out-$mode.time"
done
/usr/bin/python3 - "$out-off" "$out-vcrit" <<'PY'
import json, sys
def runs(d):
    return {r["speed_m_per_s"]: r for r in (json.loads(l)["result"] for l in open(d + "/journal.jsonl"))}
off, on = runs(sys.argv[1]), runs(sys.argv[2])
key = lambda r: (r["broken"], r["undecided"], r["projectile_contact"])
bad = [v for v in off if v not in on or key(off[v]) != key(on[v])] + [v for v in on if v not in off]
for v in sorted(off):
    if v in on:
        print(f"v = {v:.6f} m/s  broken {off[v]['broken']!s:5} undecided {off[v]['undecided']!s:5}  steps "
              f"{off[v]['steps']:7d} -> {on[v]['steps']:7d}  solves {off[v]['electrostatic_solves']:6d} -> "
              f"{on[v]['electrostatic_solves']:6d}{'  DIFFERENT' if key(off[v]) != key(on[v]) else ''}")
vc = [json.load(open(d + "/vcrit.json"))["v_crit"] for d in sys.argv[1:3]]
print(f"v_crit off {vc[0]:.6f}, on {vc[1]:.6f} m/s; {len(bad)} of {len(off)} outcomes differ")
sys.exit(1 if bad or vc[0] != vc[1] else 0)
PY
