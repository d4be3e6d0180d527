#!/usr/bin/env bash
# Budgets before work (issue 23 item 10): an ensemble of many runs is checked against the budgets from
# one run's estimate times the number of runs before its runs are made (each a parsed case): `acoustic
# --seeds 100000` spent 45 s and 1 GB, `--seeds 1000000000` did not answer in 60 s; now each is refused
# in one line, exit 2, within a few seconds (also `sweep --seeds` and with --dry-run), naming --seeds.
# With the step budget raised, the memory of the planned cases refuses 1e9 members.
source "$(dirname "$0")/lib.sh"
SHORT=(--set time.end=0.0001 --set "output.snapshot_times=[0]" --set "output.psd_times=[0]")

# quick WHAT PATTERN COMMAND...: exit 2 within 10 s of wall time, one line matching PATTERN
quick() {
  local what=$1 pattern=$2
  shift 2
  local t0 dt
  t0=$(date +%s%3N)
  timeout 10 "$A" "$@" > /dev/null 2> "$T/err"
  local rc=$?
  dt=$(($(date +%s%3N) - t0))
  [ $rc -eq 2 ] || fail "$what: exit $rc (124: no answer in 10 s): $(head -c 300 "$T/err")"
  [ "$(wc -l < "$T/err")" -eq 1 ] || fail "$what: not one line: $(head -c 300 "$T/err")"
  grep -q -- "$pattern" "$T/err" || fail "$what: $(head -c 300 "$T/err")"
  echo "ok   $what: exit 2 after $dt ms"
}
quick "acoustic --seeds 100000" "estimated steps .*driven by --seeds" acoustic "$AC" --seeds 100000
quick "acoustic --seeds 1000000000 --dry-run" "driven by --seeds" acoustic "$AC" "${SHORT[@]}" --seeds 1000000000 --dry-run
quick "sweep --seeds 1000000000" "driven by --seeds, --values" sweep "$AC" --param seed --values 1,2 --seeds 1000000000
quick "acoustic --seeds 1000000000 --max-steps 1e30" "estimated memory .*driven by --seeds" \
  acoustic "$AC" "${SHORT[@]}" --seeds 1000000000 --max-steps 1e30
echo "PASS ensemble_budget_first"
