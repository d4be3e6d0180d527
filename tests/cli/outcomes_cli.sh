#!/usr/bin/env bash
# agglo outcomes (docs/outcomes.md): a small sphere-sphere table of cases/outcomes_sphere_sphere.toml; its
# results.nc is read by the DSMC as outcomes.table (also by two ensemble members on job threads, with nothing
# on stderr); --resume reuses every journaled impact and gives the
# same table; a two-sphere target and a decreasing speed axis are refused (exit 2, one line, no folder).
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, refused

O="$SRC/cases/outcomes_sphere_sphere.toml"
G=(--set "outcome_grid.speeds=[0.1, 0.8]" --set "outcome_grid.diameters=[1e-6, 2e-6]" --set outcome_grid.impacts=3)
$A -q outcomes "$O" "${G[@]}" --out "$T/oc" > /dev/null 2>&1 || fail "outcomes failed"
/usr/bin/python3 - "$T/oc/outcomes.csv" <<'PY' || fail "outcomes.csv"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 2 * 2 * 2, len(rows)
for r in rows:
    assert int(r["impacts"]) == 3 and int(r["sticks"]) + int(r["bounces"]) + int(r["breaks"]) == 3, r
    assert abs(float(r["p_stick"]) + float(r["p_bounce"]) + float(r["p_break"]) - 1) < 1e-12, r
    assert float(r["p_stick_lo"]) <= float(r["p_stick"]) <= float(r["p_stick_hi"]), r
# 0.1 m/s sticks and 0.8 m/s bounces at these sizes (the pair's damped sticking speed is 0.2-0.6 m/s)
assert all(float(r["p_stick"]) == (1.0 if r["speed"] == "0.1" else 0.0) for r in rows), rows
PY
# --resume: the journal's 10 first impacts are reused (the first one marked as a bounce to show that it is
# read, not re-run), the 8 others run again; then the table is the first one but for that impact.
cp "$T/oc/outcomes.csv" "$T/first.csv"
head -10 "$T/oc/journal.jsonl" | sed '1s/"outcome":0/"outcome":1/' > "$T/j" && mv "$T/j" "$T/oc/journal.jsonl"
$A -q outcomes "$O" "${G[@]}" --out "$T/oc" --resume > /dev/null 2>&1 || fail "outcomes --resume failed"
[ "$(wc -l < "$T/oc/journal.jsonl")" -eq 18 ] || fail "journal after --resume: $(wc -l < "$T/oc/journal.jsonl") lines"
[ "$(diff "$T/first.csv" "$T/oc/outcomes.csv" | grep -c '^>')" -eq 1 ] || fail "--resume: $(diff "$T/first.csv" "$T/oc/outcomes.csv")"
grep -q '^0.1,1e-06,1e-06,0.66666667,.*,3,2,1,0$' "$T/oc/outcomes.csv" || fail "--resume did not read the journal"
# The DSMC reads the table.
$A -q --no-plots acoustic "$AC" --set time.end=0.005 --set "output.psd_times=[0.0,0.005]" \
  --set "output.snapshot_times=[0.0]" --set outcomes.dry_model=table --set "outcomes.table=\"$T/oc/results.nc\"" \
  --out "$T/ac" > /dev/null 2>&1 || fail "acoustic with the outcomes table failed"
grep -q "dry outcome model: table $T/oc/results.nc" "$T/ac/run.log" || fail "run.log does not name the table"
grep -q "dry outcome table: queries=" "$T/ac/run.log" || fail "run.log does not count the table queries"
# Two members read the table on two job threads: HDF5's error printing is per thread, and NetCDF turns it
# off only on the thread that initialises it; a read elsewhere printed HDF5-DIAG lines (now silenced).
$A -q --no-plots acoustic "$AC" --set time.end=0.005 --set "output.psd_times=[0.0,0.005]" \
  --set "output.snapshot_times=[0.0]" --set outcomes.dry_model=table --set "outcomes.table=\"$T/oc/results.nc\"" \
  --seeds 2 --threads 2 --out "$T/ac2" > /dev/null 2> "$T/ac2.err" || fail "acoustic --seeds 2 with the table failed"
grep -q "HDF5-DIAG" "$T/ac2.err" && fail "HDF5-DIAG lines on stderr: $(head -c 300 "$T/ac2.err")"
# Charge axes (docs/outcomes.md "Charge and permittivity"): 1 speed x 1 x 1 diameters x 2 x 2 charges, head-on;
# opposite charges stick at 0.8 m/s, like charges bounce; the DSMC reads the table with a charged population.
$A -q outcomes "$O" --set "outcome_grid.speeds=[0.8]" --set "outcome_grid.diameters=[1e-6]" --set outcome_grid.impacts=1 \
  --set outcome_grid.max_offset=0 --set "outcome_grid.charges=[-5e-5, 5e-5]" --set electrostatics.min_gap=0.05 \
  --out "$T/och" > /dev/null 2>&1 || fail "charged outcomes failed"
/usr/bin/python3 - "$T/och/outcomes.csv" <<'PY' || fail "charged outcomes.csv"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 4, rows
stick = {(float(r["charge_1"]), float(r["charge_2"])): float(r["p_stick"]) for r in rows}
assert stick[(-5e-5, 5e-5)] == 1 and stick[(5e-5, -5e-5)] == 1, stick
assert stick[(-5e-5, -5e-5)] == 0 and stick[(5e-5, 5e-5)] == 0, stick
PY
grep -q "sigma1=-5e-05 sigma2=5e-05" "$T/och/journal.jsonl" || fail "charged journal keys"
$A -q --no-plots acoustic "$AC" --set time.end=0.002 --set "output.psd_times=[0.0,0.002]" \
  --set "output.snapshot_times=[0.0]" --set outcomes.dry_model=table --set "outcomes.table=\"$T/och/results.nc\"" \
  --set population.0.charge_density=2e-5 --out "$T/acq" > /dev/null 2>&1 || fail "acoustic with a charged population failed"
grep -q "dry outcome table: queries=" "$T/acq/run.log" || fail "charged run.log does not count the table queries"
# Refusals.
sed 's/^\[time\]/[[particles]]\nposition = [5e-6, 0.0, 0.0]\nradius = 1e-6\n\n[time]/' "$O" > "$T/bad.toml"
refused outcomes "needs a one-sphere target" "two-sphere target"
sed 's/^speeds = .*/speeds = [0.4, 0.2]/' "$O" > "$T/bad.toml"
refused outcomes "outcome_grid.speeds" "decreasing speeds"
echo "ok"
