#!/usr/bin/env bash
# agglo sweep over an acoustic key: one row per value in sweep.csv, one folder per case, values in
# order; a bad key or value is rejected (exit 2) before any case runs. $1 = agglo, $2 = source dir.
. "$(dirname "$0")/lib.sh"  # A, SRC, T (removed on exit), fail
AGGLO=$A TMP=$T
fail=0
base="$SRC/cases/seed002_baseline.toml"
short=(--set time.end=0.0005 --set "output.psd_times=[0.0,0.0005]" --set "output.snapshot_times=[0.0]" --set output.plots=false)
"$AGGLO" -q sweep "$base" --out "$TMP/s" "${short[@]}" --param population.1.diameter --values 10e-6,30e-6,0 -j 2 \
  >/dev/null 2>"$TMP/s.err"
rc=$?
[ $rc -eq 0 ] || { echo "FAIL sweep exit $rc"; cat "$TMP/s.err"; fail=1; }
[ -s "$TMP/s/sweep.csv" ] || { echo "FAIL sweep.csv missing"; fail=1; }
rows=$(($(wc -l <"$TMP/s/sweep.csv") - 1))
[ "$rows" -eq 3 ] || { echo "FAIL sweep.csv has $rows rows"; fail=1; }
head -1 "$TMP/s/sweep.csv" | grep -q "population.1.diameter" || { echo "FAIL header lacks the key"; fail=1; }
head -1 "$TMP/s/sweep.csv" | grep -q "fine_efficiency" || { echo "FAIL header lacks fine_efficiency"; fail=1; }
sed -n 2p "$TMP/s/sweep.csv" | grep -q "^0,10e-6," || { echo "FAIL first row is not the first value"; fail=1; }
for d in "$TMP"/s/case_*; do [ -s "$d/summary.json" ] || { echo "FAIL $d/summary.json missing"; fail=1; }; done
grep -q '^diameter = 3' "$TMP"/s/case_01_*/config.resolved.toml && grep -q '^diameter = 1' "$TMP"/s/case_00_*/config.resolved.toml || {
  echo "FAIL case 1 config does not carry the swept value"; fail=1; }
# Invalid value -> exit 2, nothing run.
"$AGGLO" -q sweep "$base" --out "$TMP/b" "${short[@]}" --param population.0.geometric_std --values 2.0,0.5 \
  >/dev/null 2>"$TMP/b.err"
rc=$?
[ $rc -eq 2 ] || { echo "FAIL bad value: exit $rc"; cat "$TMP/b.err"; fail=1; }
[ ! -e "$TMP/b/case_00_2.0/summary.json" ] || { echo "FAIL a case ran before validation failed"; fail=1; }
exit $fail
