#!/usr/bin/env bash
# `agglo acoustic CASE --seeds N` (a seeded sweep with no axes, run/ensemble_request.hpp): member folders,
# sweep.csv, ensemble_summary.csv, ensemble_timeseries.csv and results.nc with the mean and stderr of every
# variable; run.json records the command acoustic (not sweep); --seeds 1 is the single run; a member missing from the journal (deleted, or cut off by SIGINT) is run again by --resume
# and the outputs equal the uninterrupted run's (wall times aside); bad --seeds values and --checkpoint
# with an ensemble are refused with one line, exit 2. $1 = agglo executable, $2 = source dir.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, AC, NT
SHORT=(--set time.end=0.01 --set "output.psd_times=[0.0,0.01]" --set "output.snapshot_times=[0.0]"
       --set output.plots=false --set population.0.samples=1500 --set population.1.samples=50)
run() { "$A" -q --no-plots acoustic "$AC" "${SHORT[@]}" "$@"; }

# The ensemble outputs of folders $1 and $2 agree: results.nc by content, the CSV tables without their
# wall-time row / column, every member's results.nc.
same_ensemble() {
  /usr/bin/python3 "$SRC/tests/cli/same_results_nc.py" "$1/results.nc" "$2/results.nc" || return 1
  cmp -s <(grep -v '^wall_time_s,' "$1/ensemble_summary.csv") <(grep -v '^wall_time_s,' "$2/ensemble_summary.csv") ||
    { echo "ensemble_summary.csv differs"; return 1; }
  cmp -s "$1/ensemble_timeseries.csv" "$2/ensemble_timeseries.csv" || { echo "ensemble_timeseries.csv differs"; return 1; }
  local m
  for m in "$1"/case_*; do
    /usr/bin/python3 "$SRC/tests/cli/same_results_nc.py" "$m/results.nc" "$2/$(basename "$m")/results.nc" || return 1
  done
}

run --seeds 3 --out "$T/e" -j 2 > /dev/null 2> "$T/err" || fail "--seeds 3: $(cat "$T/err")"
for f in sweep.csv ensemble_summary.csv ensemble_timeseries.csv results.nc journal.jsonl run.json; do
  [ -s "$T/e/$f" ] || fail "$f missing"
done
members=$(ls -d "$T"/e/case_* | wc -l)
[ "$members" -eq 3 ] || fail "$members member folders, expected 3"
[ -d "$T"/e/case_00_20230064702 ] || fail "member 0 does not run the case's own seed 20230064702"
[ "$(wc -l < "$T/e/journal.jsonl")" -eq 3 ] || fail "journal.jsonl does not hold 3 members"
/usr/bin/python3 - "$T/e/run.json" <<'PY' || fail "run.json: $(cat "$T/e/run.json")"
import json, sys
r = json.load(open(sys.argv[1]))
d = r["details"]
assert r["command"] == "acoustic" and r["status"] == "complete", r
assert d["command"] == "acoustic" and d["ensemble"] == "seeds" and d["members"] == 3, d
assert d["seeds"][0] == 20230064702 and len(set(d["seeds"])) == 3 and "param" not in d, d
PY
[ -e "$T/e/sweep_ensemble.csv" ] && fail "a seed ensemble without axes wrote the points' table"
# a seed ensemble is not a sweep: `sweep --resume` refuses its folder, naming the command acoustic
cp -r "$T/e" "$T/notsweep"
"$A" -q --no-plots sweep "$AC" "${SHORT[@]}" --param population.1.diameter --values 20e-6 --out "$T/notsweep" \
  --resume > /dev/null 2> "$T/err" && fail "sweep --resume took an acoustic --seeds folder"
grep -q "acoustic" "$T/err" || fail "sweep --resume of an ensemble folder: $(cat "$T/err")"
# ... nor a single run: `acoustic --resume` without --seeds refuses it with one line, exit 2, folder kept
run --out "$T/notsweep" --resume > /dev/null 2> "$T/err"; rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < "$T/err")" -eq 1 ] && grep -q "journal.jsonl" "$T/err" ||
  fail "acoustic --resume of an ensemble folder: exit $rc: $(cat "$T/err")"
cmp -s "$T/e/run.json" "$T/notsweep/run.json" || fail "a refused single run changed the ensemble's run.json"
head -1 "$T/e/ensemble_summary.csv" | grep -qx 'quantity,unit,mean,stderr,n' || fail "ensemble_summary.csv header"
grep -q '^fine_efficiency,1,[0-9.e-]*,[0-9.e-]*,3$' "$T/e/ensemble_summary.csv" || fail "no fine_efficiency row with n = 3"
grep -q '^n_solid_final_cm3,cm-3,' "$T/e/ensemble_summary.csv" || fail "no n_solid_final_cm3 row"
head -1 "$T/e/ensemble_timeseries.csv" | grep -q '^t_s,.*fine_efficiency_mean,fine_efficiency_stderr' ||
  fail "ensemble_timeseries.csv header"
/usr/bin/python3 - "$T/e" <<'PY' || fail "results.nc"
import csv, sys
import netCDF4
import numpy as np
out = sys.argv[1]
with netCDF4.Dataset(out + "/results.nc") as d:
    assert d.getncattr("members") == 3, d.getncattr("members")
    seeds = list(d.getncattr("seeds"))
    assert seeds[0] == 20230064702 and len(set(seeds)) == 3, seeds
    assert list(d["member_seed"][:]) == seeds
    for name in ("fine_efficiency", "n_solid_cm3", "solid_dNdlogd_cm3", "n_solid_final_cm3"):
        m, e = d[name + "_mean"], d[name + "_stderr"]
        assert m.dimensions == e.dimensions and m.units == e.units, name
    assert d["solid_dNdlogd_cm3_mean"].dimensions == ("psd_time", "diameter")
    eff = d["fine_efficiency_mean"][:]
    # the mean of the members' own results.nc
    own = []
    for s in seeds:
        import glob
        (folder,) = glob.glob(f"{out}/case_*_{s}")
        with netCDF4.Dataset(folder + "/results.nc") as m:
            own.append(m["fine_efficiency"][:])
    own = np.array(own)
    assert np.allclose(eff, own.mean(axis=0), rtol=1e-14, atol=0), (eff, own.mean(axis=0))
    se = own.std(axis=0, ddof=1) / np.sqrt(3)
    assert np.allclose(d["fine_efficiency_stderr"][:], se, rtol=1e-12, atol=1e-300)
    assert se[-1] > 0
PY
echo "ok   --seeds 3: member folders, tables and results.nc"

# --seeds 1 is the single run.
run --seeds 1 --out "$T/one" -j 2 > /dev/null 2>&1 || fail "--seeds 1"
run --out "$T/plain" -j 2 > /dev/null 2>&1 || fail "plain run"
[ -e "$T/one/ensemble_summary.csv" ] && fail "--seeds 1 wrote ensemble tables"
cmp -s "$T/one/efficiency.csv" "$T/plain/efficiency.csv" || fail "--seeds 1 efficiency.csv differs from the single run"
/usr/bin/python3 "$SRC/tests/cli/same_results_nc.py" "$T/one/results.nc" "$T/plain/results.nc" || fail "--seeds 1 results.nc"
echo "ok   --seeds 1 = the single run"

# A member lost (its journal line and folder deleted, a torn line appended as by kill -9): --resume runs
# it again, and only it.
cp -r "$T/e" "$T/r"
stamp=$(stat -c %y "$T"/r/case_00_*/run.json)
grep -v '"index":1,' "$T/e/journal.jsonl" > "$T/r/journal.jsonl"
printf '{"context":"torn' >> "$T/r/journal.jsonl"
rm -rf "$T"/r/case_01_* "$T/r/results.nc" "$T/r/ensemble_summary.csv"
run --seeds 3 --out "$T/r" -j 2 --resume > /dev/null 2> "$T/err" || fail "--resume: $(cat "$T/err")"
[ "$(stat -c %y "$T"/r/case_00_*/run.json)" = "$stamp" ] || fail "--resume ran member 0 again"
same_ensemble "$T/e" "$T/r" || fail "resumed ensemble differs"
echo "ok   --resume after a lost member: identical"

# A larger ensemble extends a smaller one: --seeds 4 --resume runs member 3 only.
cp -a "$T/e" "$T/x"
run --seeds 4 --out "$T/x" -j 2 --resume > /dev/null 2> "$T/err" || fail "--seeds 4 --resume: $(cat "$T/err")"
[ "$(stat -c %y "$T"/x/case_01_*/run.json)" = "$(stat -c %y "$T"/e/case_01_*/run.json)" ] || fail "extension reran member 1"
[ "$(ls -d "$T"/x/case_* | wc -l)" -eq 4 ] && grep -q '^fine_efficiency,1,[0-9.e-]*,[0-9.e-]*,4$' "$T/x/ensemble_summary.csv" ||
  fail "extended ensemble does not have 4 members"
echo "ok   --seeds 4 --resume extends a 3-member ensemble"

# Interrupted by SIGINT after the first member is in the journal (longer members, one at a time); --resume
# completes it.
LONG=(--set time.end=0.06 --set "output.psd_times=[0.0,0.06]")
run --seeds 3 "${LONG[@]}" --out "$T/l" -j 2 > /dev/null 2>&1 || fail "long ensemble"
"$A" -q --no-plots acoustic "$AC" "${SHORT[@]}" --seeds 3 "${LONG[@]}" --out "$T/i" -j 1 > /dev/null 2>&1 &
pid=$!
for _ in $(seq 1 400); do [ -s "$T/i/journal.jsonl" ] && break; sleep 0.02; done
kill -INT $pid 2> /dev/null
wait $pid; rc=$?
[ $rc -eq 130 ] || [ $rc -eq 0 ] || fail "SIGINT: exit $rc"
[ $rc -eq 0 ] || grep -q '"status": "incomplete"' "$T/i/run.json" || fail "interrupted run.json not incomplete"
[ $rc -eq 0 ] || [ "$(wc -l < "$T/i/journal.jsonl")" -lt 3 ] || fail "SIGINT: every member in the journal"
run --seeds 3 "${LONG[@]}" --out "$T/i" -j 2 --resume > /dev/null 2> "$T/err" || fail "--resume after SIGINT: $(cat "$T/err")"
same_ensemble "$T/l" "$T/i" || fail "ensemble resumed after SIGINT (exit $rc) differs"
echo "ok   SIGINT (exit $rc) and --resume: identical"

# --format csv: no results.nc; --dry-run: the cost of all members, nothing written.
run --seeds 2 --out "$T/c" -j 2 --format csv > /dev/null 2>&1 || fail "--format csv"
[ -e "$T/c/results.nc" ] && fail "--format csv wrote results.nc"
[ -s "$T/c/ensemble_timeseries.csv" ] || fail "--format csv: no ensemble_timeseries.csv"
single=$(run --dry-run | awk '/^  steps/ {print $2}')
three=$(run --dry-run --seeds 3 | awk '/^  steps/ {print $2}')
/usr/bin/python3 -c "import sys; a, b = map(float, sys.argv[1:]); sys.exit(0 if abs(b - 3 * a) <= 1e-2 * b else 1)" \
  "$single" "$three" || fail "dry run: $three steps for 3 members, $single for one"
run --dry-run --seeds 3 --out "$T/dry" > /dev/null || fail "--dry-run --seeds"
[ -e "$T/dry" ] && fail "--dry-run made the folder"

# Refused with one line, exit 2.
for v in 0 -2 abc 1.5 ""; do
  run --seeds "$v" --out "$T/bad" > /dev/null 2> "$T/err"; rc=$?
  [ $rc -eq 2 ] || fail "--seeds '$v': exit $rc"
  [ "$(wc -l < "$T/err")" -eq 1 ] && grep -q -- '--seeds' "$T/err" || fail "--seeds '$v': $(cat "$T/err")"
done
run --seeds 2 --checkpoint 0.005 --out "$T/bad" > /dev/null 2> "$T/err"; rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < "$T/err")" -eq 1 ] || fail "--checkpoint with --seeds 2: exit $rc $(cat "$T/err")"
[ -e "$T/bad" ] && fail "a refused run made its folder"
echo "ok   bad --seeds values and --checkpoint refused"
exit 0
