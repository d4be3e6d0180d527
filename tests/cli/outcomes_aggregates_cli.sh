#!/usr/bin/env bash
# agglo outcomes with aggregate partners (docs/outcomes.md "Aggregate tables"): a tiny table of
# cases/outcomes_aggregates.toml (2 speeds x primary counts 2, 3 x 2 impacts) has the volume-equivalent
# diameters 2 a N^(1/3) as its size axes, the fragment statistics where pairs broke (NaN elsewhere), and
# is read by the DSMC as outcomes.table; primary counts with a one-sphere target are refused.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, refused

O="$SRC/cases/outcomes_aggregates.toml"
G=(--set "outcome_grid.speeds=[0.1, 10.0]" --set "outcome_grid.primaries=[2, 3]" --set outcome_grid.impacts=2)
$A -q outcomes "$O" "${G[@]}" --out "$T/oa" > /dev/null 2>&1 || fail "outcomes failed"
/usr/bin/python3 - "$T/oa/outcomes.csv" <<'PY' || fail "outcomes.csv"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 2 * 2 * 2, len(rows)
a = 0.5e-6
assert sorted({float(r["diameter_1"]) for r in rows}) == [float(f"{2 * a * n ** (1 / 3):.8g}") for n in (2, 3)], rows
for r in rows:
    assert int(r["impacts"]) == 2 and int(r["sticks"]) + int(r["bounces"]) + int(r["breaks"]) == 2, r
    assert abs(float(r["p_stick"]) + float(r["p_bounce"]) + float(r["p_break"]) - 1) < 1e-12, r
    nf, fl = float(r["fragments"]), float(r["largest_fraction"])
    if int(r["breaks"]) == 0:
        assert math.isnan(nf) and math.isnan(fl), r
    else:
        assert nf >= 2 and 1 / nf <= fl < 1, r
# 0.1 m/s sticks; 10 m/s breaks every pair (cases/outcomes_aggregates.toml)
assert all(r["p_stick"] == "1" for r in rows if r["speed"] == "0.1"), rows
assert all(r["p_break"] == "1" for r in rows if r["speed"] == "10"), rows
PY
# The DSMC reads the aggregate table (its P_break > 0 nodes need the fragment statistics).
$A -q --no-plots acoustic "$AC" --set time.end=0.005 --set "output.psd_times=[0.0,0.005]" \
  --set "output.snapshot_times=[0.0]" --set outcomes.dry_model=table --set "outcomes.table=\"$T/oa/results.nc\"" \
  --out "$T/ac" > /dev/null 2>&1 || fail "acoustic with the aggregate outcomes table failed"
grep -q "dry outcome model: table $T/oa/results.nc" "$T/ac/run.log" || fail "run.log does not name the table"
grep -q "aggregate-aggregate impacts" "$T/ac/run.log" || fail "run.log lacks the table's provenance"
# Primary radii (docs/outcomes.md "Primary radii"): 4 primaries of a_0 = 0.5 um and 2 of 2^(1/3) a_0 on the
# common diameter 2 a_0 4^(1/3); the axes primary_radius_1/2 in the table, the journal keys with each
# partner's count and radius, --resume from a truncated journal gives the same table, a DSMC run reads it.
R=(--set "outcome_grid.speeds=[0.1, 10.0]" --set "outcome_grid.primaries=[4]" --set outcome_grid.impacts=1
   --set "outcome_grid.primary_radii=[0.5e-6, 6.299605249474366e-7]")
$A -q outcomes "$O" "${R[@]}" --out "$T/or" > /dev/null 2>&1 || fail "outcomes with primary radii failed"
head -1 "$T/or/outcomes.csv" | grep -q '^speed,diameter_1,diameter_2,primary_radius_1,primary_radius_2,p_stick' ||
  fail "primary-radius columns: $(head -1 "$T/or/outcomes.csv")"
[ "$(wc -l < "$T/or/outcomes.csv")" -eq 9 ] || fail "primary radii: $(wc -l < "$T/or/outcomes.csv") lines, 2 x 4 nodes + header"
grep -q '"key":"v_n=10 n1=4 n2=2 a1=5e-07 a2=6.299605249474366e-07 ' "$T/or/journal.jsonl" || fail "journal keys with radii"
cp "$T/or/outcomes.csv" "$T/or.csv"
head -3 "$T/or/journal.jsonl" > "$T/j" && mv "$T/j" "$T/or/journal.jsonl"
$A -q outcomes "$O" "${R[@]}" --out "$T/or" --resume > /dev/null 2>&1 || fail "outcomes --resume with primary radii"
cmp -s "$T/or.csv" "$T/or/outcomes.csv" || fail "--resume with primary radii: $(diff "$T/or.csv" "$T/or/outcomes.csv")"
[ "$(wc -l < "$T/or/journal.jsonl")" -eq 6 ] || fail "journal after --resume: $(wc -l < "$T/or/journal.jsonl") lines"
$A -q --no-plots acoustic "$AC" --set time.end=0.005 --set "output.psd_times=[0.0,0.005]" \
  --set "output.snapshot_times=[0.0]" --set outcomes.dry_model=table --set "outcomes.table=\"$T/or/results.nc\"" \
  --out "$T/acr" > /dev/null 2>&1 || fail "acoustic with the primary-radius table failed"
sed 's/^primaries = .*/primaries = [4]\nprimary_radii = [0.5e-6, 0.6e-6]/' "$O" > "$T/bad.toml"
refused outcomes "outcome_grid.primary_radii" "primary radii giving 2.31 primaries"
# Refusals: primary counts with the one-sphere target; both axes.
sed 's/^diameters = .*/primaries = [2, 4]/' "$SRC/cases/outcomes_sphere_sphere.toml" > "$T/bad.toml"
refused outcomes "agglomerate.shape" "primaries with a sphere target"
sed 's/^primaries = .*/primaries = [2, 4]\ndiameters = [1e-6, 2e-6]/' "$O" > "$T/bad.toml"
refused outcomes "not both" "primaries and diameters"
echo "ok"
