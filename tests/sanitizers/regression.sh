#!/usr/bin/env bash
# Output regression in the sanitizer build (AGGLO_SANITIZE): tests/regression/check.sh, i.e. every
# shipped case must run (any sanitizer report makes its run fail) and every output must match the
# stored checksums, except the files listed in regression_allowed_diffs.txt, which explains why they
# may differ there. Those files must still be written. The runs of regression_skipped_runs.txt are left
# out (their folders' files are then reported missing and not counted against the build).
# Usage: regression.sh AGGLO_EXECUTABLE SOURCE_DIR
set -u
A=$1; SRC=$2
skipped=$(grep -v '^#' "$SRC/tests/sanitizers/regression_skipped_runs.txt" | sed '/^$/d')
out=$(AGGLO_SKIP_RUNS="$(echo $skipped)" bash "$SRC/tests/regression/check.sh" "$A" "$SRC" 2>&1)
rc=$?
echo "$out"
[ $rc -eq 0 ] && exit 0
allowed=$(grep -v '^#' "$SRC/tests/sanitizers/regression_allowed_diffs.txt" | sed '/^$/d; s/^/differs: /')
# missing: <stem>-<command>/... of a skipped <command>:<stem>
skipped_dirs=$(printf '%s\n' "$skipped" | sed -E 's|^([^:]+):(.*)$|^missing: \2-\1/|')
unexpected=$(printf '%s\n' "$out" | grep -E '^(differs|missing|new file|FAIL)' | grep -vxF -- "$allowed" |
             grep -vE -- "${skipped_dirs:-^$}")
if [ -n "$unexpected" ] || ! printf '%s\n' "$out" | grep -q ' files checked, '; then
  echo "FAIL: differences not explained by tests/sanitizers/regression_allowed_diffs.txt:"
  printf '%s\n' "$unexpected"
  exit 1
fi
echo "ok: the only differences are the files of regression_allowed_diffs.txt"
