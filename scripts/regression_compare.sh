#!/usr/bin/env bash
# Builds an earlier commit (default: the pre-refactor baseline 31f1010, see tests/regression/) in a
# temporary worktree, runs every shipped case with both that build and the current build/agglo on
# this machine, and compares the normalised outputs file by file.
# Usage: scripts/regression_compare.sh [COMMIT]     (run from anywhere inside the checkout)
set -euo pipefail
cd "$(dirname "$0")/.."
REF=${1:-31f1010}
W=$(mktemp -d); trap 'git worktree remove --force "$W/src" >/dev/null 2>&1 || true; rm -rf "$W"' EXIT
git worktree add --detach "$W/src" "$REF" >/dev/null
cmake -S "$W/src" -B "$W/build" -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=/usr/bin/python3 \
      -DAGGLO_BUILD_TESTS=OFF -DAGGLO_BUILD_BENCH=OFF >/dev/null
cmake --build "$W/build" -j"$(nproc)" --target agglo >/dev/null
[ -x build/agglo ] || { echo "build/agglo missing: run scripts/setup.sh first" >&2; exit 2; }
bash tests/regression/run_cases.sh "$W/build/agglo" . "$W/old"
bash tests/regression/run_cases.sh build/agglo . "$W/new"
/usr/bin/python3 tests/regression/checksums.py "$W/old" > "$W/old.sums"
echo "comparing current build against $REF:"
rc=0
/usr/bin/python3 tests/regression/checksums.py "$W/new" --compare "$W/old.sums" | tee "$W/report" || rc=$?
# Show what differs in each differing text file (the raw files; timing fields are not stripped here).
sed -n 's/^differs: //p' "$W/report" | while read -r f; do
  echo "--- $f"
  diff "$W/old/$f" "$W/new/$f" | head -6
done
exit $rc
