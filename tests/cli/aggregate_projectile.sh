#!/usr/bin/env bash
# Aggregate-aggregate impacts (docs/dem.md "Aggregate projectiles"): cases/aggregate_aggregate.toml
# runs (two 8-primary BPCA aggregates stick head-on at 0.05 m/s), breakup samples orientations of both;
# misplaced keys of an aggregate projectile -> one line naming file, key and value, exit 2, no folder.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail

C="$SRC/cases/aggregate_aggregate.toml"
start=$SECONDS
$A -q --no-plots collide "$C" --out "$T/aa" > /dev/null 2>&1 || fail "aggregate_aggregate collide failed"
[ $((SECONDS - start)) -lt 30 ] || fail "aggregate_aggregate took $((SECONDS - start)) s (limit 30 s)"
/usr/bin/python3 - "$T/aa/result.json" <<'PY' || fail "aggregate_aggregate result"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["projectile_contact"] and not r["broken"], r["broken"]
assert r["components"] == [list(range(16))], r["components"]
PY
grep -q "^shape = 'bpca'" "$T/aa/config.resolved.toml" || fail "resolved config lacks the projectile shape"
$A -q --no-plots breakup "$C" --set 'breakup.speeds=[0.05]' --set breakup.orientations=2 --out "$T/ab" > /dev/null 2>&1 \
  || fail "aggregate_aggregate breakup failed"
grep -q 'orientation=1/2' "$T/ab/journal.jsonl" || fail "breakup journal lacks the second orientation"

bad() {  # bad <expected fragment> <sed expression on the case>
  sed "$2" "$C" > "$T/bad.toml"
  rm -rf "$T/out"
  $A collide "$T/bad.toml" --out "$T/out" > /dev/null 2> "$T/stderr"
  [ $? -eq 2 ] || fail "expected exit 2 for: $2"
  [ "$(wc -l < "$T/stderr")" -eq 1 ] || fail "error must be one line: $(cat "$T/stderr")"
  grep -qF -- "$1" "$T/stderr" || fail "message lacks '$1': $(cat "$T/stderr")"
  grep -qF "bad.toml" "$T/stderr" || fail "message lacks file name: $(cat "$T/stderr")"
  [ ! -e "$T/out" ] || fail "output folder created despite the error"
}
P='/^\[projectile\]/,/^\[time\]/'  # sed range: the [projectile] table
bad "projectile.seed' = 2: applies to shape" "$P"' { s/^shape = "bpca"/shape = "sphere"/; /^primaries = 8$/d; /^orientation/d; }'
bad "projectile.charge' = 1e-15: applies to a sphere projectile" 's/^orientation = "random"/orientation = "random"\ncharge = 1e-15/'
bad "projectile.shape' = \"cube\"" "$P"' s/^shape = "bpca"/shape = "cube"/'
echo "ok"
