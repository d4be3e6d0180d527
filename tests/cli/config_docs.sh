#!/usr/bin/env bash
# docs/config.md must be what `agglo config --markdown` prints from the settings tables (regenerate
# with: build/agglo config --markdown > docs/config.md).
# Usage: config_docs.sh AGGLO_EXECUTABLE SOURCE_DIR
set -u
A=$1; SRC=$2
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
"$A" config --markdown > "$T/config.md" || { echo "FAIL: agglo config --markdown failed"; exit 1; }
if ! diff -u "$SRC/docs/config.md" "$T/config.md"; then
  echo "FAIL: docs/config.md is stale; regenerate it with: agglo config --markdown > docs/config.md"
  exit 1
fi
echo "ok"
