# Shared by tests/cli/*.sh (sourced; not a test): $1 = agglo executable, $2 = source dir.
#   A    the agglo executable     SRC  the source dir     T  a temporary folder, removed on exit (even when a
#                                                            test left read-only folders in it)
#   AC   the seed-002 baseline case (acoustic)            NT the neutral seed-000 tetrahedron (DEM)
#   fail MESSAGE: prints "FAIL: MESSAGE" and exits 1
set -u
A=$1; SRC=$2
T=$(mktemp -d); trap 'chmod -R u+w "$T" 2>/dev/null; rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
AC="$SRC/cases/seed002_baseline.toml"
NT="$SRC/cases/seed000_neutral_tetrahedron.toml"
