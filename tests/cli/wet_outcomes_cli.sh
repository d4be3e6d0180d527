#!/usr/bin/env bash
# outcomes.wet_model = "table" (docs/acoustics.md §1.7): the seed-002 case (droplets scavenge fly ash, so wet
# pairs occur) reads a sphere-sphere table written by agglo outcomes as its wet table; run.log names it and
# counts its queries, summary.json and results.nc report them (nanbu_wet_outcome_table_*), and the dry table
# counters stay absent (dry pairs keep the critical velocity). Bad input is refused with exit 2, one line
# naming the key and the case file, and no output folder: wet_table without wet_model = "table", wet_model =
# "table" without wet_table, a missing file, a NetCDF file that is not an outcome table, an unknown model.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, refused

O="$SRC/cases/outcomes_sphere_sphere.toml"
$A -q outcomes "$O" --set "outcome_grid.speeds=[0.01, 0.8]" --set "outcome_grid.diameters=[0.5e-6, 20e-6]" \
  --set outcome_grid.impacts=1 --out "$T/tab" > /dev/null 2>&1 || fail "agglo outcomes failed"
short=(--set time.end=0.005 --set "output.psd_times=[0.0,0.005]" --set "output.snapshot_times=[0.0]")
$A -q --no-plots acoustic "$AC" "${short[@]}" --set outcomes.wet_model=table \
  --set "outcomes.wet_table=\"$T/tab/results.nc\"" --out "$T/wet" > /dev/null 2>&1 || fail "acoustic with a wet table failed"
grep -q "wet outcome model: table $T/tab/results.nc" "$T/wet/run.log" || fail "run.log does not name the wet table"
grep -q "wet outcome table: queries=" "$T/wet/run.log" || fail "run.log does not count the wet table queries"
grep -q "dry outcome table" "$T/wet/run.log" && fail "run.log reports a dry table the run does not have"
/usr/bin/python3 - "$T/wet" <<'PY' || fail "summary.json / results.nc counters of the wet table"
import json, sys
import netCDF4
d = sys.argv[1]
n = json.load(open(d + "/summary.json"))["nanbu"]
assert "outcome_table_queries" not in n, n
q = n["wet_outcome_table_queries"]
assert q > 0 and q == n["coalescences"]["wet"] + n["rebounds"]["wet"], n
assert 0 <= n["wet_outcome_table_clamped"] <= q, n
with netCDF4.Dataset(d + "/results.nc") as nc:
    assert int(nc["nanbu_wet_outcome_table_queries"][...]) == q
PY
# Refusals (the case's [outcomes] table gets the lines).
bad() { sed "s|^\[outcomes\]|[outcomes]\n$1|" "$AC" > "$T/bad.toml"; }
bad 'wet_table = "'"$T"'/tab/results.nc"'
refused acoustic "is read only with outcomes.wet_model = \"table\"" "wet_table without wet_model"
bad 'wet_model = "table"'
refused acoustic "key 'outcomes.wet_table'" "wet_model without wet_table"
bad 'wet_model = "table"\nwet_table = "'"$T"'/absent.nc"'
refused acoustic "cannot read $T/absent.nc" "missing wet table"
bad 'wet_model = "table"\nwet_table = "'"$T"'/wet/results.nc"'
refused acoustic "not an outcome table" "a results.nc of the DSMC as the wet table"
bad 'wet_model = "tabel"'
refused acoustic "outcomes.wet_model" "unknown wet model"
echo "ok"
