#!/usr/bin/env bash
# Checkpoint and exact restart of `agglo sectional` (docs/restart.md): a run killed in the middle of a
# checkpoint write (fault hook AGGLO_FAULT_KILL_CHECKPOINT=N) and continued with --resume ends with the
# uninterrupted run's files (run.json and wall times aside; results.nc by content) and final checkpoint.bin, byte for byte; a
# checkpoint of another config is refused with one line, exit 2. $1 = agglo executable, $2 = source dir.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, AC, NT
CASE="$SRC/cases/partmc_brownian.toml"
SHORT=(--set time.end=7200.0 --set "output.psd_times=[0.0,3600.0,7200.0]" --set output.plots=false)
run() { "$A" -q --no-plots sectional "$CASE" "${SHORT[@]}" --checkpoint 900 "$@"; }
blank() { sed 's/wall_time=[0-9.]* s/wall_time=X/; s/"wall_time_s": *[0-9.e+-]*/"wall_time_s": 0/' "$1"; }

run --out "$T/full" > /dev/null 2>&1 || fail "uninterrupted run"
[ -f "$T/full/checkpoint.bin" ] || fail "no checkpoint.bin"
for N in 1 4 8; do
  d="$T/kill$N"
  AGGLO_FAULT_KILL_CHECKPOINT=$N run --out "$d" > /dev/null 2>&1; rc=$?
  [ $rc -eq 137 ] || fail "kill at checkpoint $N: exit $rc (expected 137)"
  run --out "$d" --resume > /dev/null 2> "$T/err" || fail "resume after kill $N: $(cat "$T/err")"
  for f in "$T/full"/*; do
    n=$(basename "$f")
    [ "$n" = run.json ] && continue
    if [ "$n" = results.nc ]; then  # by content, the wall-clock timing variable aside
      /usr/bin/python3 "$SRC/tests/cli/same_results_nc.py" "$f" "$d/$n" || fail "resume after kill at checkpoint $N: $n differs"
      continue
    fi
    cmp -s <(blank "$f") <(blank "$d/$n") || fail "resume after kill at checkpoint $N: $n differs"
  done
  echo "ok   killed during checkpoint write $N, resumed: identical"
done
run --out "$T/kill4" --resume --set sectional.tolerance=1e-5 > /dev/null 2> "$T/err"; rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < "$T/err")" -eq 1 ] && grep -q "config hash.*cannot be resumed" "$T/err" \
  || fail "resume with another config: exit $rc: $(cat "$T/err")"
echo "ok   other config refused: $(cat "$T/err")"
