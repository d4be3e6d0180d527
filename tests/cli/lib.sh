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
# refused COMMAND FRAGMENT WHAT: `agglo COMMAND $T/bad.toml --out $T/out` must exit 2 with one line on
# stderr that holds FRAGMENT and the file name, and leave no output folder (WHAT names the mutation).
refused() {
  local cmd=$1 frag=$2 what=$3 rc
  rm -rf "$T/out"
  $A "$cmd" "$T/bad.toml" --out "$T/out" > "$T/stdout" 2> "$T/stderr"
  rc=$?
  [ $rc -eq 2 ] || fail "expected exit 2, got $rc for: $what"
  [ "$(wc -l < "$T/stderr")" -eq 1 ] || fail "error must be one line: $(cat "$T/stderr")"
  grep -qF -- "$frag" "$T/stderr" || fail "message lacks '$frag': $(cat "$T/stderr")"
  grep -qF "bad.toml" "$T/stderr" || fail "message lacks file name: $(cat "$T/stderr")"
  [ ! -e "$T/out" ] || fail "output folder created despite the error: $(ls "$T/out")"
}
