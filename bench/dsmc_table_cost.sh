#!/usr/bin/env bash
# Cost of the DSMC's tabulated dry outcome against the closed-form default (issue 26: at most 1.2x per
# sample-step; docs/acoustics.md §1.7 "Cost"), callgrind instructions of Engine::step (inclusive), one
# thread, in one script so that the variants share the machine, the build and the case:
#   case   4000 + 4000 solid samples of 1 and 10 um (monodisperse, 2500 kg/m^3, 1e12 m^-3 each) in a
#          140 dB, 2 kHz travelling wave, constant kernel K = 4.5e-10 m^3/s, 20 collision steps of 1e-4 s
#          (a collision-heavy case: most collisions are dry)
#   default  outcomes.dry_model absent (v_cr,dry, eq. 13)
#   table    the 6 x 3 x 3 sphere table of cases/outcomes_sphere_sphere.toml (agglo outcomes; P_break = 0)
#   break    the same table with P_stick and P_bounce scaled by 0.7 and P_break = 0.3, N_f = 3, f_L = 0.5
#            (written with netCDF4-python, Debian python3-netcdf4)
#   wet_default, wet_table  the case with the 10 um population liquid (droplets: fine-droplet pairs coalesce
#            into mixed particles, whose pairs with the fine ones are wet), without and with the sphere table
#            as the wet table (outcomes.wet_model = "table"; docs/acoustics.md §1.7 "Wet pairs")
# Prints per variant: Engine::step instructions per sample-step, the ratio to the default (wet_table: to
# wet_default), the dry (wet) collisions and how many stuck, bounced and broke; and OutcomeTable's share.
#   bench/dsmc_table_cost.sh [AGGLO] [OUT_DIR]
#   CALLGRIND=0: the runs without valgrind (no instruction counts; the collision counts only).
#   SMOKE=1: the smoke test (ctest -L bench): 2 steps instead of 20, CALLGRIND=0 unless set (a callgrind run
#   costs ~3 s even at 10 steps); the same table, variants and collision counts.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
AGGLO=$(realpath "${1:-$SRC/build/agglo}")
OUT=$(realpath -m "${2:-$SRC/results/bench_dsmc_table_cost}")
mkdir -p "$OUT"
export OMP_NUM_THREADS=1
STEPS=20
DT=1e-4
if [ "${SMOKE:-0}" = 1 ]; then
  STEPS=2 CALLGRIND=${CALLGRIND:-0}
  [ "$CALLGRIND" = 1 ] || echo "smoke: callgrind skipped (collision counts only)"
fi
CALLGRIND=${CALLGRIND:-1}

cat > "$OUT/case.toml" <<EOF
seed = 26
[sound]
level_db = 140.0
frequency_hz = 2000.0
[domain]
cells_x = 100
[time]
end = $(/usr/bin/python3 -c "print($STEPS * $DT)")
collision_dt = $DT
motion_dt = $DT
[kernels]
model = "constant"
constant_coefficient = 4.5e-10
[[population]]
name = "fine"
phase = "solid"
distribution = "monodisperse"
diameter = 1e-6
number_concentration = 1e12
density = 2500.0
samples = 4000
[[population]]
name = "coarse"
phase = "solid"
distribution = "monodisperse"
diameter = 10e-6
number_concentration = 1e12
density = 2500.0
samples = 4000
[output]
psd_times = [0.0]
snapshot_times = []
EOF
# The wet case: the coarse population as droplets (water).
sed '/^name = "coarse"/,/^samples/{s/^phase = "solid"/phase = "liquid"/;s/^density = 2500.0/density = 1000.0/}' \
  "$OUT/case.toml" > "$OUT/case_wet.toml"

"$AGGLO" -q --no-plots outcomes "$SRC/cases/outcomes_sphere_sphere.toml" --out "$OUT/outcomes" --overwrite --threads 1 > /dev/null
/usr/bin/python3 - "$OUT/outcomes/results.nc" "$OUT/table_break.nc" <<'PY'
import shutil, sys
import netCDF4
shutil.copy(sys.argv[1], sys.argv[2])
with netCDF4.Dataset(sys.argv[2], "a") as d:
    dims = d["p_stick"].dimensions
    d["p_stick"][:] = 0.7 * d["p_stick"][:]
    d["p_bounce"][:] = 0.7 * d["p_bounce"][:]
    d["p_break"][:] = 0.3
    for name, value in (("fragments", 3.0), ("largest_fraction", 0.5)):
        v = d[name] if name in d.variables else d.createVariable(name, "f8", dims)
        v.units = "1"
        v[:] = value
PY

run() {  # run LABEL [--set ...]
  local label=$1; shift
  local pre=(valgrind --tool=callgrind --callgrind-out-file="$OUT/callgrind_$label.out")
  [ "$CALLGRIND" = 1 ] || { pre=(); rm -f "$OUT/callgrind_$label.txt"; }
  "${pre[@]}" "$AGGLO" -q --no-plots acoustic "${CASE:-$OUT/case.toml}" --out "$OUT/$label" --overwrite --threads 1 --format csv "$@" \
    > /dev/null 2> "$OUT/callgrind_$label.log"
  [ "$CALLGRIND" = 1 ] || return 0
  callgrind_annotate --inclusive=yes --threshold=100 "$OUT/callgrind_$label.out" > "$OUT/callgrind_$label.txt" 2> /dev/null
}
run default
run table --set outcomes.dry_model=table --set "outcomes.table=\"$OUT/outcomes/results.nc\""
run break --set outcomes.dry_model=table --set "outcomes.table=\"$OUT/table_break.nc\""
CASE="$OUT/case_wet.toml" run wet_default
CASE="$OUT/case_wet.toml" run wet_table --set outcomes.wet_model=table --set "outcomes.wet_table=\"$OUT/outcomes/results.nc\""

/usr/bin/python3 - "$OUT" "$STEPS" "$CALLGRIND" <<'PY'
import csv, json, re, sys
out, steps, callgrind = sys.argv[1], int(sys.argv[2]), sys.argv[3] == "1"
def inclusive(label, prefix):  # 1 without callgrind (no counts)
    if not callgrind:
        return 1
    best = 0
    for line in open(f"{out}/callgrind_{label}.txt"):
        m = re.match(r"\s*([\d,]+) \(\s*[\d.]+%\)\s+(.*)$", line)
        if m and ":" in m.group(2) and m.group(2).split(":", 1)[1].startswith(prefix):
            best = max(best, int(m.group(1).replace(",", "")))
    return best
rows = {}
for label in ("default", "table", "break", "wet_default", "wet_table"):
    n = json.load(open(f"{out}/{label}/summary.json"))["samples"]
    step = inclusive(label, "agglo::acoustics::Engine::step(")
    at = inclusive(label, "agglo::acoustics::OutcomeTable::at(")
    frag = inclusive(label, "agglo::acoustics::OutcomeTable::fragments_at(")
    brk = inclusive(label, "agglo::acoustics::break_weighted(")
    kind = "wet" if label.startswith("wet") else "dry"
    dry = next(r for r in csv.DictReader(open(f"{out}/{label}/outcomes_by_pair.csv")) if r["pair_type"] == kind)
    rows[label] = (step / (n * steps), step, at, frag, brk, dry, kind)
print(f"Engine::step, callgrind, one thread, {steps} steps; instructions per sample-step (ratio to the default)"
      if callgrind else f"{steps} steps without callgrind: no instruction counts")
for label, (per, step, at, frag, brk, dry, kind) in rows.items():
    base = rows["wet_default" if kind == "wet" else "default"][0]
    counts = (f"{per:8.1f} ({per / base:.3f}x)  Engine::step {step / 1e6:.1f}e6  OutcomeTable::at {at / 1e6:.2f}e6"
              f"  fragments_at {frag / 1e6:.2f}e6  break_weighted {brk / 1e6:.2f}e6" if callgrind else "")
    print(f"  {label:11} {counts}  {kind} collisions {dry['pair_collisions']}:"
          f" stuck {dry['stuck']}, bounced {dry['bounced']}, broke {dry['broke']}")
PY
