#!/usr/bin/env bash
# `agglo sweep ... --seeds N` (run/ensemble_request.hpp, run/seed_ensemble.hpp): every point of the grid runs
# the same N member seeds (the seed as the last axis); sweep_ensemble.csv / sweep_ensemble.nc give each point's
# scalar means and standard errors, and each point's folder point_<p>_<value> the whole statistics (time
# series, size distributions) of `agglo acoustic --seeds N` at that value. Checked against independent
# computations: the statistics recomputed from sweep.csv's rows (mean, s.e. with n - 1), member 0 of each
# point equal to the plain sweep's case, each point's files equal to `agglo acoustic --seeds N` at that
# value, 1 and 2 threads identical, --resume after a lost member equal;
# bad --seeds uses refused with one line, exit 2, no folder. $1 = agglo executable, $2 = source dir.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, AC, NT
SHORT=(--set time.end=0.01 --set "output.psd_times=[0.0,0.01]" --set "output.snapshot_times=[0.0]"
       --set population.0.samples=1500 --set population.1.samples=50)
P=(--param population.1.diameter --values 20e-6,40e-6)
sweep() { "$A" -q --no-plots sweep "$AC" "${SHORT[@]}" "${P[@]}" "$@"; }
untimed() {  # a CSV table without its wall-time columns
  /usr/bin/python3 -c 'import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
keep = [i for i, h in enumerate(rows[0]) if "wall_time" not in h]
print("\n".join(",".join(r[i] for i in keep) for r in rows))' "$1"
}

sweep --seeds 3 --out "$T/s" -j 2 > /dev/null 2> "$T/err" || fail "--seeds 3: $(cat "$T/err")"
for f in sweep.csv sweep_ensemble.csv sweep_ensemble.nc results.nc journal.jsonl run.json; do
  [ -s "$T/s/$f" ] || fail "$f missing"
done
[ "$(ls -d "$T"/s/case_* | wc -l)" -eq 6 ] || fail "expected 2 points x 3 members = 6 case folders"
[ "$(wc -l < "$T/s/journal.jsonl")" -eq 6 ] || fail "journal.jsonl does not hold 6 runs"
grep -q '"members": 3' "$T/s/run.json" || fail "run.json details lack the members"
grep -q '"command": "sweep"' "$T/s/run.json" || fail "run.json does not record the sweep"
for p in point_00_20e-6 point_01_40e-6; do
  for f in ensemble_summary.csv ensemble_timeseries.csv results.nc; do
    [ -s "$T/s/$p/$f" ] || fail "$p/$f missing"
  done
done

# the statistics, recomputed from the runs' rows of sweep.csv, and the NetCDF copy of the table
/usr/bin/python3 - "$T/s" <<'PY' || fail "sweep_ensemble.csv/.nc disagree with the runs in sweep.csv"
import csv, math, sys
import netCDF4
d = sys.argv[1]
runs = list(csv.DictReader(open(f"{d}/sweep.csv")))
pts = list(csv.DictReader(open(f"{d}/sweep_ensemble.csv")))
nc = netCDF4.Dataset(f"{d}/sweep_ensemble.nc")
assert len(pts) == 2 and [p["population.1.diameter"] for p in pts] == ["20e-6", "40e-6"], pts
seeds = [r["seed"] for r in runs[:3]]
assert [r["seed"] for r in runs[3:]] == seeds, "the points must share their member seeds"
for i, p in enumerate(pts):
    assert p["members"] == "3" and p["case"] == runs[3 * i]["case"], p
    for q in ("fine_efficiency", "n_solid_final_cm3", "nanbu.coalescences.wet"):
        x = [float(r[q]) for r in runs[3 * i:3 * i + 3]]
        m = sum(x) / 3
        s = math.sqrt(sum((v - m) ** 2 for v in x) / 2 / 3)
        assert abs(float(p[q + "_mean"]) - m) <= 1e-9 * abs(m), (q, p[q + "_mean"], m)
        assert abs(float(p[q + "_stderr"]) - s) <= 1e-8 * abs(m), (q, p[q + "_stderr"], s)
        assert abs(nc[q + "_mean"][i] - float(p[q + "_mean"])) <= 1e-9 * abs(m)
        assert abs(nc[q + "_stderr"][i] - float(p[q + "_stderr"])) <= 1e-9 * abs(m) + 1e-300
    assert s > 0, "three seeds gave the same result"
assert list(nc["population.1.diameter"][:]) == [20e-6, 40e-6] and list(nc["members"][:]) == [3, 3]
PY

# member 0 of each point is the plain sweep's case (the case's own seed)
sweep --out "$T/plain" -j 2 > /dev/null 2>&1 || fail "plain sweep"
/usr/bin/python3 - "$T/plain/sweep.csv" "$T/s/sweep.csv" <<'PY' || fail "member 0 differs from the plain sweep's case"
import csv, sys
plain = list(csv.DictReader(open(sys.argv[1])))
seeded = list(csv.DictReader(open(sys.argv[2])))
for i, r in enumerate(plain):
    assert r["fine_efficiency"] == seeded[3 * i]["fine_efficiency"], (r, seeded[3 * i])
PY

# each point equals the seed ensemble of the case at that value (agglo acoustic --seeds)
"$A" -q --no-plots acoustic "$AC" "${SHORT[@]}" --set population.1.diameter=40e-6 --seeds 3 --out "$T/e" -j 2 \
  > /dev/null 2>&1 || fail "acoustic --seeds 3"
/usr/bin/python3 - "$T/e/ensemble_summary.csv" "$T/s/sweep_ensemble.csv" <<'PY' || fail "point 1 differs from acoustic --seeds 3"
import csv, sys
ens = {r["quantity"]: r for r in csv.DictReader(open(sys.argv[1]))}
pt = list(csv.DictReader(open(sys.argv[2])))[1]
for q in ("fine_efficiency", "n_solid_final_cm3", "nanbu.coalescences.dry"):
    assert ens[q]["mean"] == pt[q + "_mean"] and ens[q]["stderr"] == pt[q + "_stderr"], (q, ens[q], pt)
PY
# ... and so are its files: the time series and size distributions (results.nc), not only the scalars
cmp -s "$T/e/ensemble_timeseries.csv" "$T/s/point_01_40e-6/ensemble_timeseries.csv" ||
  fail "point_01's ensemble_timeseries.csv differs from acoustic --seeds 3"
cmp -s <(grep -v '^wall_time_s,' "$T/e/ensemble_summary.csv") \
  <(grep -v '^wall_time_s,' "$T/s/point_01_40e-6/ensemble_summary.csv") || fail "point_01's ensemble_summary.csv differs"
/usr/bin/python3 - "$T/e/results.nc" "$T/s/point_01_40e-6/results.nc" <<'PY' || fail "point_01's results.nc differs"
import sys
import netCDF4
import numpy as np
with netCDF4.Dataset(sys.argv[1]) as e, netCDF4.Dataset(sys.argv[2]) as p:
    names = [n for n in e.variables if n.endswith("_mean") or n.endswith("_stderr")]
    assert "solid_dNdlogd_cm3_mean" in names and p["solid_dNdlogd_cm3_mean"].dimensions == ("psd_time", "diameter")
    for n in names:
        if n.startswith("wall_time"):
            continue
        assert np.array_equal(e[n][:], p[n][:], equal_nan=True), n
PY

# 1 thread: identical; a lost member (journal line and folder removed) is run again by --resume
sweep --seeds 3 --out "$T/one" -j 1 > /dev/null 2>&1 || fail "--seeds 3 on one thread"
cmp -s <(untimed "$T/s/sweep_ensemble.csv") <(untimed "$T/one/sweep_ensemble.csv") || fail "1 and 2 threads differ"
cmp -s "$T/s/point_00_20e-6/ensemble_timeseries.csv" "$T/one/point_00_20e-6/ensemble_timeseries.csv" ||
  fail "1 and 2 threads: point_00's time series differ"
sed -i '4d' "$T/one/journal.jsonl" && rm -rf "$T"/one/case_04_*
sweep --seeds 3 --out "$T/one" -j 2 --resume > /dev/null 2> "$T/err" || fail "--resume: $(cat "$T/err")"
cmp -s <(untimed "$T/s/sweep_ensemble.csv") <(untimed "$T/one/sweep_ensemble.csv") || fail "--resume differs"

# refusals: one line, exit 2, no folder
refused() {
  local what=$1; shift
  "$A" -q --no-plots sweep "$@" --out "$T/bad" > /dev/null 2> "$T/err"; local rc=$?
  [ $rc -eq 2 ] || fail "$what: exit $rc, expected 2"
  [ "$(wc -l < "$T/err")" -eq 1 ] || fail "$what: not one line: $(cat "$T/err")"
  grep -q -- "--seeds" "$T/err" || fail "$what: the message does not name --seeds: $(cat "$T/err")"
  [ -e "$T/bad" ] && fail "$what: made the folder"
  return 0
}
refused "--seeds 0" "$AC" "${SHORT[@]}" "${P[@]}" --seeds 0
refused "--seeds with the seed swept" "$AC" "${SHORT[@]}" --param seed --values 1,2 --seeds 2
refused "--seeds for a command without seed" "$SRC/cases/seed000_neutral_tetrahedron.toml" --command collide \
  --param projectile.speed --values 0.1,0.2 --seeds 2
"$A" -q --no-plots sweep "$AC" "${SHORT[@]}" "${P[@]}" --seeds x --out "$T/bad" > /dev/null 2>&1
[ $? -eq 2 ] && [ ! -e "$T/bad" ] || fail "--seeds x must exit 2 without a folder"
echo "sweep --seeds: all checks passed"
