#!/usr/bin/env bash
# Checks before work (issue 9 items 6 and 8, docs/limits.md): a case whose estimated steps, memory or
# output exceeds its budget is refused with exit 2, one line naming the driving key, the budget and
# how to raise it, and no output folder; budgets come from --max-* before AGGLO_MAX_* before the
# defaults; bad budget values are one-line errors; --dry-run validates and prints the estimates of
# every shipped case within the default budgets without creating anything.
# $1 = agglo executable, $2 = source dir.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, AC, NT
unset AGGLO_MAX_STEPS AGGLO_MAX_MEMORY AGGLO_MAX_OUTPUT
DEM="$SRC/cases/seed000_neutral_tetrahedron.toml"
ES="$SRC/cases/electrostatics_tetrahedron.toml"

# err <expected fragment> <agglo args...>: exit 2, one line on stderr holding the fragment, no folder.
err() {
  local frag=$1; shift
  rm -rf "$T/out"
  $A -q --no-plots "$@" --out "$T/out" > "$T/stdout" 2> "$T/stderr"
  local rc=$?
  [ $rc -eq 2 ] || fail "expected exit 2, got $rc for: $*: $(cat "$T/stderr")"
  [ "$(wc -l < "$T/stderr")" -eq 1 ] || fail "error must be one line for $*: $(cat "$T/stderr")"
  grep -qF -- "$frag" "$T/stderr" || fail "message lacks '$frag' for $*: $(cat "$T/stderr")"
  [ ! -e "$T/out" ] || fail "output folder left behind for $*: $(ls -A "$T/out")"
}

# Typos that ran for ever: refused by the step budget, naming the key and how to raise the budget.
err "time.dt" collide "$DEM" --set time.dt=1e-300
err "raise the budget with --max-steps or AGGLO_MAX_STEPS" collide "$DEM" --set time.dt=1e-300
err "material.surface_energy" collide "$DEM" --set material.surface_energy=1e300
err "time.after_contact" collide "$DEM" --set time.after_contact=1e300
err "material.density" collide "$DEM" --set material.density=2.5e-9
err "agglomerate.radius" collide "$DEM" --set agglomerate.radius=5e-15
err "time.after_contact" vcrit "$DEM" --set time.after_contact=1e300
err "breakup.samples" breakup "$DEM" --set breakup.samples=100000 --set time.after_contact=1
err "time.end" acoustic "$AC" --set time.end=1e300
err "the step budget" sweep "$DEM" --command collide --param time.after_contact --values 2e-3,1e300

# Memory and output: BEM patches, snapshot times, spheres, samples.
err "electrostatics.patches_per_sphere" electrostatics "$ES" --set electrostatics.solver=bem \
  --set electrostatics.patches_per_sphere=1000000
SNAP=$(/usr/bin/python3 -c "print('[' + ','.join('%g' % (i * 4e-4) for i in range(10000)) + ']')")
err "output.snapshot_times" acoustic "$AC" --set "output.snapshot_times=$SNAP"
err "--max-output or AGGLO_MAX_OUTPUT" acoustic "$AC" --set "output.snapshot_times=$SNAP"
err "the memory budget" acoustic "$AC" --set time.end=1e-4 --set population.1.samples=99000000 \
  --set "output.psd_times=[0.0]" --set "output.snapshot_times=[0.0]"
err "population.samples" acoustic "$AC" --set time.end=1e-4 --set population.1.samples=99000000 \
  --set "output.psd_times=[0.0]" --set "output.snapshot_times=[0.0]"
/usr/bin/python3 - "$T/many.toml" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write('[electrostatics]\nsolver = "spectral"\n')
    for i in range(100000):
        f.write('[[particles]]\nposition = [%g, %g, %g]\nradius = 1e-5\ncharge = 1e-15\n'
                % ((i % 100) * 3e-5, (i // 100 % 100) * 3e-5, (i // 10000) * 3e-5))
PY
err "[[particles]]" electrostatics "$T/many.toml"
err "the memory budget" electrostatics "$T/many.toml"

# A list agglomerate of 32 000 touching [[particles]] (a 32 x 32 x 32 lattice less 768): its overlap check
# is O(N) (the DEM's cell grid), so --dry-run answers at once; the exhaustive pair scan took 34 s of CPU.
/usr/bin/python3 - "$T/list.toml" << 'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write('[agglomerate]\nshape = "list"\n')
    for i in range(32000):
        f.write("[[particles]]\nposition = [%g, %g, %g]\nradius = 1e-6\n"
                % (2e-6 * (i % 32), 2e-6 * (i // 32 % 32), 2e-6 * (i // 1024)))
PY
/usr/bin/python3 - "$A" "$T/list.toml" << 'PY' || fail "--dry-run of a 32 000-particle list agglomerate"
import resource, subprocess, sys
r = subprocess.run([sys.argv[1], "-q", "collide", sys.argv[2], "--dry-run", "--max-output", "1T"],
                   capture_output=True, text=True, timeout=60)
cpu = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = cpu.ru_utime + cpu.ru_stime
assert r.returncode == 0 and "valid; estimated cost" in r.stdout, (r.returncode, r.stdout, r.stderr)
assert cpu < 3.0, f"{cpu:.2f} s of CPU"  # 0.5 s measured
print(f"ok   --dry-run of 32000 list particles: {cpu:.2f} s of CPU")
PY
sed -i 's/^position = \[0, 0, 0\]/position = [1e-6, 0, 0]/' "$T/list.toml"  # entry 0 half inside entry 1
refusal=$($A -q collide "$T/list.toml" --dry-run 2>&1 >/dev/null)
[[ "$refusal" == *"[[particles]] entries 0 and 1 overlap by 1e-06 m"* ]] || fail "overlap in a large list: $refusal"

# Budgets: command line before environment before defaults; a low budget refuses a shipped case.
err "the step budget 1e+03" collide "$DEM" --max-steps 1000
AGGLO_MAX_STEPS=1000 err "the step budget 1e+03" collide "$DEM"
AGGLO_MAX_STEPS=1000 $A -q --no-plots collide "$DEM" --max-steps 1e9 --set time.after_contact=1e-5 \
  --set output.snapshot_interval=0 --out "$T/ok" > /dev/null 2>&1 || fail "--max-steps must override AGGLO_MAX_STEPS"
[ -f "$T/ok/result.json" ] || fail "a run within its budgets writes its results"
err "the memory budget 1 KiB" electrostatics "$ES" --max-memory 1K
AGGLO_MAX_MEMORY=1K err "AGGLO_MAX_MEMORY" electrostatics "$ES"
err "the output budget 1 KiB" electrostatics "$ES" --max-output 1K
AGGLO_MAX_OUTPUT=2K err "--max-output" acoustic "$AC"
err "the memory budget 1 KiB" sweep "$AC" --param population.1.diameter --values 10e-6,30e-6 --max-memory 1K

# Bad budget values: one line naming the option or variable, the value and what is allowed.
err "--max-memory = '12X'" collide "$DEM" --max-memory 12X
err "K, M, G or T" collide "$DEM" --max-output=-1G
err "--max-steps = 'lots'" vcrit "$DEM" --max-steps lots
err "--max-steps = '0'" acoustic "$AC" --max-steps 0
AGGLO_MAX_MEMORY=8GB err "AGGLO_MAX_MEMORY = '8GB'" electrostatics "$ES"
AGGLO_MAX_STEPS=-3 err "AGGLO_MAX_STEPS = '-3'" breakup "$DEM"
AGGLO_MAX_OUTPUT= err "AGGLO_MAX_OUTPUT = ''" sweep "$DEM" --command collide --param projectile.speed --values 0.1

# --dry-run: every shipped case with the commands it is for passes the default budgets, prints the
# three estimates and creates nothing; an over-budget dry run is refused like the run itself.
dry() {  # dry <agglo args...>
  rm -rf "$T/out"
  $A -q "$@" --out "$T/out" --dry-run > "$T/stdout" 2> "$T/stderr" || fail "dry run failed: $*: $(cat "$T/stderr")"
  for q in steps memory output; do
    grep -qE "^  $q .* ok " "$T/stdout" || fail "dry run of $* lacks '$q ... ok': $(cat "$T/stdout")"
  done
  [ ! -e "$T/out" ] || fail "dry run created the output folder: $*"
  [ ! -s "$T/stderr" ] || fail "dry run wrote to stderr: $*: $(cat "$T/stderr")"
}
for c in "$SRC"/cases/seed000_*.toml; do
  for cmd in collide vcrit breakup; do dry $cmd "$c"; done
done
for c in "$SRC"/cases/electrostatics_*.toml; do dry electrostatics "$c"; done
dry electrostatics "$ES" --set electrostatics.solver=bem
for c in "$SRC"/cases/seed002_*.toml; do dry acoustic "$c"; done
dry sweep "$AC" --param population.1.diameter --values 10e-6,30e-6
dry sweep "$DEM" --command vcrit --param material.surface_energy --values 0.01,0.02
grep -q "driven by .*population.samples" <(
  $A -q acoustic "$AC" --dry-run) || fail "dry run names the keys driving the estimates"
rm -rf "$T/out"
$A -q collide "$DEM" --set time.dt=1e-300 --out "$T/out" --dry-run > "$T/stdout" 2> "$T/stderr"
[ $? -eq 2 ] || fail "an over-budget dry run exits 2"
grep -q "^  steps .* EXCEEDS .*time.dt" "$T/stdout" || fail "an over-budget dry run shows which estimate: $(cat "$T/stdout")"
[ ! -e "$T/out" ] || fail "an over-budget dry run created the output folder"
rm -rf "$T/out"
$A -q collide "$DEM" --dry-run --set material.density=-1 --out "$T/out" > /dev/null 2> "$T/stderr"
[ $? -eq 2 ] && grep -q "material.density" "$T/stderr" || fail "--dry-run validates the case"
echo "budgets: ok"
