#!/usr/bin/env bash
# Output regression test: every shipped case, shortened (run_cases.sh), must give outputs whose
# normalised checksums (checksums.py: timing and provenance fields stripped, PNGs skipped) equal the
# stored baseline tests/regression/checksums.txt. Checksums were recorded on Debian 12 x86_64; libm
# differs between machines, so on another platform compare against an older build with
# scripts/regression_compare.sh instead.
# Usage: check.sh AGGLO_EXECUTABLE SOURCE_DIR
set -u
A=$1; SRC=$2
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
bash "$SRC/tests/regression/run_cases.sh" "$A" "$SRC" "$T/out" || { echo "FAIL: a case did not run"; exit 1; }
/usr/bin/python3 "$SRC/tests/regression/checksums.py" "$T/out" --compare "$SRC/tests/regression/checksums.txt"
