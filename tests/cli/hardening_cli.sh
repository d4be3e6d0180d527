#!/usr/bin/env bash
# Hardening contract (issue 9): malformed --set/--param/--values, empty case files, CLI11 parse errors
# and unusable output folders give exit 2 with exactly one line (control characters escaped) and no
# output folder; sweep.csv quotes its fields; stale temporary files and snapshots never survive a
# later run. $1 = agglo executable, $2 = source dir.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, AC, NT
DEM=$NT
SHORT_AC=(--set time.end=0.001 --set "output.psd_times=[0.0,0.001]" --set "output.snapshot_times=[0.0]"
          --set output.plots=false)

# err <expected fragment> <agglo args...>: exit 2, one line on stderr holding the fragment, no folder.
err() {
  local frag=$1; shift
  rm -rf "$T/out"
  $A -q --no-plots "$@" > "$T/stdout" 2> "$T/stderr"
  local rc=$?
  [ $rc -eq 2 ] || fail "expected exit 2, got $rc for: $*: $(cat "$T/stderr")"
  [ "$(wc -l < "$T/stderr")" -eq 1 ] || fail "error must be one line for $*: $(cat "$T/stderr")"
  grep -qF -- "$frag" "$T/stderr" || fail "message lacks '$frag' for $*: $(cat "$T/stderr")"
  [ ! -e "$T/out" ] || fail "output folder left behind for $*: $(ls -A "$T/out")"
}

# Item 1: a key of only whitespace must not crash any command.
for cmd in collide vcrit breakup; do
  err "--set" $cmd "$DEM" --out "$T/out" --set ' =5'
  err "--set" $cmd "$DEM" --out "$T/out" --set $'\t=5'
done
err "--set" acoustic "$AC" --out "$T/out" --set ' =5'
err "--set" electrostatics "$SRC/cases/electrostatics_two_spheres.toml" --out "$T/out" --set $' \t =5'
err "--param" sweep "$DEM" --command collide --out "$T/out" --param ' ' --values 1
err "given more than once" sweep "$DEM" --command collide --out "$T/out" --param projectile.speed --values 0.1 --param projectile.speed --values 0.2

# Item 11: trailing dot, two assignments in one --set, trailing comma in --values.
err "empty key segment" collide "$DEM" --out "$T/out" --set material.density.=2500
err "one KEY=VALUE assignment per --set" collide "$DEM" --out "$T/out" --set $'material.density=2500\nbogus=1'
err "empty entry" sweep "$DEM" --command collide --out "$T/out" --param material.density --values 2500,
err "empty entry" sweep "$DEM" --command collide --out "$T/out" --param material.density --values ,2500

# Item 13: an empty case file is an error, not the built-in defaults.
: > "$T/empty.toml"
for cmd in collide vcrit breakup acoustic electrostatics; do
  err "empty.toml: empty case file" $cmd "$T/empty.toml" --out "$T/out"
done

# Item 14: messages on one line with control characters and U+2028 escaped; CLI11 errors one line.
err 'density=a\nb' collide "$DEM" --out "$T/out" --set $'material.density=a\nb'
err 'col\x01our' collide "$DEM" --out "$T/out" --set $'material.col\x01our=1'
err '\u2028' collide "$DEM" --out "$T/out" --set $'material.col\u2028our=1'
err "--threads" collide "$DEM" --out "$T/out" --threads -1
grep -q '[0-9]\{30\}' "$T/stderr" && fail "--threads -1 prints a huge bound: $(cat "$T/stderr")"
err "--bogus" collide "$DEM" --out "$T/out" --bogus
err "subcommand" --out "$T/out"
$A --help > /dev/null || fail "--help"
$A --version | grep -q agglo || fail "--version"

# Item 10: validation errors found by the engine or in a later sweep case leave no folder.
err "time.max_subcycles" acoustic "$AC" --out "$T/out" "${SHORT_AC[@]}" --set time.max_subcycles=1 \
  --set time.collision_dt=1e-3
err "material.density" sweep "$DEM" --command collide --out "$T/out" --param material.density --values 2500,-1

# Item 7: an unusable output folder is exit 2 naming it, before any computation.
err "output folder /proc/x" collide "$DEM" --out /proc/x
err "output folder /proc/self" collide "$DEM" --out /proc/self
touch "$T/file"
err "output folder $T/file/sub" collide "$DEM" --out "$T/file/sub"
mkdir -p "$T/ro" && chmod 555 "$T/ro"
if ! touch "$T/ro/probe" 2>/dev/null; then  # root writes anywhere: checked only for other users
  $A -q --no-plots collide "$DEM" --out "$T/ro" > /dev/null 2> "$T/stderr"
  [ $? -eq 2 ] && [ "$(wc -l < "$T/stderr")" -eq 1 ] && grep -qF "output folder $T/ro" "$T/stderr" \
    || fail "read-only folder: $(cat "$T/stderr")"
fi

# sweep.csv: RFC 4180 quoting of a value holding a quote; plain values stay unquoted.
$A -q --no-plots sweep "$SRC/cases/electrostatics_two_spheres.toml" --command electrostatics \
  --param electrostatics.solver --values '"coulomb",spectral' --out "$T/s" > /dev/null 2> "$T/stderr" \
  || fail "sweep with a quoted value: $(cat "$T/stderr")"
sed -n 2p "$T/s/sweep.csv" | grep -q '^0,"""coulomb""",case_00__coulomb_,' || fail "quoted field: $(sed -n 2p "$T/s/sweep.csv")"
sed -n 3p "$T/s/sweep.csv" | grep -q '^1,spectral,case_01_spectral,' || fail "plain field: $(sed -n 3p "$T/s/sweep.csv")"

# Item 9: orphaned temporary files of a killed run are removed by the next run into the folder (a
# live process's are kept); a re-run of collide (--overwrite) does not keep the earlier run's snapshots.
SHORT=(--set time.after_contact=2e-4)
mkdir -p "$T/c"
sleep 60 & LIVE=$!
DEAD=$(bash -c 'echo $$')
touch "$T/c/result.json.tmp-$DEAD" "$T/c/run.json.tmp-$LIVE"
$A -q --no-plots collide "$DEM" --out "$T/c" "${SHORT[@]}" --set output.snapshot_interval=1e-5 > /dev/null 2>&1 \
  || fail "collide with snapshots"
kill $LIVE
[ -e "$T/c/result.json.tmp-$DEAD" ] && fail "orphaned tmp file kept"
[ -e "$T/c/run.json.tmp-$LIVE" ] || fail "tmp file of a live process removed"
rm -f "$T/c/run.json.tmp-$LIVE"
touch "$T/c/snapshots/particles_0000.vtp.tmp-$DEAD"
n1=$(ls "$T/c/snapshots" | wc -l)
[ "$n1" -gt 2 ] && [ -s "$T/c/particles.pvd" ] || fail "first run wrote no snapshots"
$A -q --no-plots collide "$DEM" --out "$T/c" "${SHORT[@]}" --set output.snapshot_interval=0 --overwrite \
  > /dev/null 2>&1 || fail "collide re-run"
[ -z "$(ls -A "$T/c/snapshots" 2>/dev/null)" ] || fail "stale snapshots kept: $(ls "$T/c/snapshots" | head -3)"
[ -e "$T/c/particles.pvd" ] && fail "stale particles.pvd kept"
[ -s "$T/c/result.json" ] || fail "re-run lacks result.json"
ls -R "$T/c" | grep -q 'tmp-' && fail "temporary files left behind"
echo "ok"
