#!/usr/bin/env bash
# Smoke test of one Google Benchmark executable of bench/ (CTest bench.<executable>, label bench;
# bench/README.md "Smoke tests"): the benchmarks matching FILTER (its smallest sizes; without FILTER the
# first one --benchmark_list_tests names, by convention the smallest) for a minimal time. Fails when the
# executable fails, runs no benchmark or reports an error (SkipWithError: "error_occurred" in its JSON).
# No timing is asserted.
#   tests/bench/gbench_smoke.sh EXECUTABLE [FILTER]
set -euo pipefail
exe=$1
filter=${2:-}
if [ -z "$filter" ]; then
  filter="^$("$exe" --benchmark_list_tests | head -n 1)\$"
fi
out=$(mktemp)
trap 'rm -f "$out"' EXIT
OMP_NUM_THREADS=1 "$exe" --benchmark_filter="$filter" --benchmark_min_time=0.001 --benchmark_format=json > "$out"
grep -E '^ +"(name|real_time|time_unit)":' "$out"
if ! grep -q '^ *"name":' "$out" || grep -q '"error_occurred": *true' "$out"; then
  cat "$out"
  echo "FAIL: $exe --benchmark_filter='$filter': no benchmark ran, or one reported an error"
  exit 1
fi
