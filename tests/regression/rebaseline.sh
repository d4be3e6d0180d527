#!/usr/bin/env bash
# Re-records tests/regression/checksums.txt from the current build, for a change that MEANS to alter
# outputs. First list what changes and why: `bash tests/regression/check.sh build/agglo .` names every
# differing file; explain each one in the commit message / issue note before re-baselining.
# Usage: tests/regression/rebaseline.sh [BUILD_DIR]   (run from the repository root)
set -euo pipefail
cd "$(dirname "$0")/../.."
B=${1:-build}
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
bash tests/regression/run_cases.sh "$B/agglo" . "$T/out"
# The "Changes explained" block is kept; add a line to it for this change by hand afterwards.
sed -n '/^# Changes explained/,/^[^#]/p' tests/regression/checksums.txt | grep '^#' > "$T/explained" || true
{
  echo "# Output checksums of tests/regression/run_cases.sh at commit $(git rev-parse --short=12 HEAD), made by"
  echo "# tests/regression/checksums.py; Debian 12 x86_64, g++ 12.2, --threads 2."
  cat "$T/explained"
  /usr/bin/python3 tests/regression/checksums.py "$T/out"
} > tests/regression/checksums.txt
echo "rebaseline: tests/regression/checksums.txt rewritten ($(grep -vc '^#' tests/regression/checksums.txt) files)"
