#!/usr/bin/env bash
# Smoke test of one bench/ script (CTest bench.<script>, label bench; bench/README.md "Smoke tests"): the
# script at its tiny sizes (SMOKE=1, what it shrinks and skips is in its header), into a temporary folder.
# Fails when the script fails (a renamed setting, a missing output column, a broken parser all stop it:
# every script runs under set -e) or when its output lacks the line that carries its result. No timing is
# asserted. A script without an entry below fails here: every bench/ script gets one (CMakeLists.txt adds
# a test per bench/*.sh).
#   tests/bench/script_smoke.sh NAME AGGLO BUILD_DIR SOURCE_DIR [MPIRUN]
set -euo pipefail
name=$1 AGGLO=$2 BUILD=$3 SRC=$4
export MPIRUN=${5:-mpirun}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
export SMOKE=1
log=$T/stdout.txt

run() { bash "$SRC/bench/$name.sh" "$@" > "$log"; }
expect() {  # a regular expression (grep -E) the output must match
  grep -Eq -- "$1" "$log" || { cat "$log"; echo "FAIL: bench/$name.sh printed no line matching: $1"; exit 1; }
}
# LAMMPS (bench/lammps/), one process without mpirun each: OpenMPI starts it without its orted daemon and
# with the self transport only (0.15 instead of 0.21 s of CPU per lmp process; the scripts start 1 to 3).
# Not for mpirun, whose ranks need the shared-memory transport.
lammps_singleton() { export OMPI_MCA_ess_singleton_isolated=1 OMPI_MCA_btl=self OMPI_MCA_pml=ob1; }
expect_file() {
  [ -s "$1" ] || { cat "$log"; echo "FAIL: bench/$name.sh left no $1"; exit 1; }
}

case $name in
  acoustic_baseline_wall_time)
    run "$AGGLO" "$T/out"
    expect '^run 1: simulation [0-9.]+ s, fine efficiency [0-9.]+; process [0-9.]+ s$' ;;
  acoustic_studies)
    run "$AGGLO" "$T/out"
    for f in int_exact_1e-5_s1/summary.json int_explicit_1e-7_s1/summary.json baseline/summary.json; do
      expect_file "$T/out/$f"
    done
    for s in droplet_diameter droplet_concentration validation droplet_diameter_seeds droplet_concentration_seeds; do
      expect_file "$T/out/$s/sweep.csv"
    done ;;
  breakup_job_cost)
    run "$AGGLO" "$T/out"
    expect '^slowest/fastest: user CPU ([0-9.]+x|-.*), steps [0-9.]+x; sum user' ;;
  dem_benchmarks)
    lammps_singleton
    BUILD=$BUILD run "$T/out"
    expect '^  pure simulation, one collision: agglo [0-9.]+ ms CPU / [0-9.]+ ms wall \(BM_Collision2ms\) vs LAMMPS loop [0-9.]+ ms \(median\) -> [0-9.]+x \(CPU\)'
    # a second run into the same folder is refused
    if BUILD=$BUILD run "$T/out" 2> "$T/stderr.txt"; then
      echo "FAIL: bench/$name.sh reran into the existing $T/out without --overwrite"; exit 1
    fi ;;
  dem_block_vs_lammps)
    lammps_singleton
    BUILD=$BUILD run "$T/out"
    expect '^ +block +1000 +[0-9]+ +[0-9]+ +[0-9]+ +[0-9]+ +[0-9.]+x +[0-9.]+x +[0-9.]+x$'
    expect '^ *aggregate_wall +207 +[0-9]+ +[0-9]+ +[0-9]+ +[0-9]+ +[0-9.]+x +[0-9.]+x +[0-9.]+x$'
    expect '^path (eight|four) pairs at a time'
    expect '^aggregate on the wall, lammps : KE after the last step [0-9.]+e-[0-9]+ J$'
    expect '^threads, N = 1000: wall [0-9.]+ s on 1, [0-9.]+ s on 2 -> speed-up [0-9.]+x$' ;;
  charged_aggregate_wall)
    run "$AGGLO" "$T/out"
    expect '^held-force error at the [0-9]+ measured solves: largest [0-9.e+-]+, mean [0-9.e+-]+'
    expect '^extrapolated to 1 ms after contact' ;;
  dsmc_migration)
    run "$AGGLO" "$T/out"
    for ax in x y z; do expect "^  $ax-slabs, K = 256 \(width [0-9.e+-]+ mm\): [0-9]+ of [0-9]+ samples change slab"; done ;;
  dsmc_sample_cost)
    run "$AGGLO" "$T/out"
    expect '^scale 4: [0-9]+ samples in 400 cells: -?[0-9]+ ns user CPU'
    expect '^  resident bytes per sample \(slope from the previous size\): -?[0-9]+$'
    expect '^checkpoint scale 4: [0-9]+ bytes for [0-9]+ samples = [0-9.]+ bytes per sample$' ;;
  dsmc_sample_scaling)
    run "$AGGLO" "$T/out"
    expect '^ +400 +400 +-?[0-9.]+ s \( *([0-9.-]+x|-) for 2x samples\) +-?[0-9.]+ ms +[0-9.]+ +[0-9.]+ +[0-9]+$' ;;
  dsmc_table_cost)
    run "$AGGLO" "$T/out"
    expect '^  break +dry collisions [0-9]+: stuck [0-9]+, bounced [0-9]+, broke [1-9][0-9]*$' ;;
  dem_threads)  # (the before/after variants with this build as BEFORE_BUILD)
    BUILD=$BUILD BEFORE_BUILD=$BUILD VARIANTS="t1 t2 t1_before t2_before" run "$T/out"
    for s in block_10000 collide; do
      expect "^$s: medians over 1 rounds \\(1-min load average [0-9.]+-[0-9.]+\\)$"
    done
    [ "$(grep -Ec '^  t2(_before)? +wall +[0-9.]+ s  CPU +[0-9.]+ s  speed-up [0-9.]+x, CPU [0-9.]+x of t1(_before)?$' "$log")" = 4 ] ||
      { cat "$log"; echo "FAIL: bench/$name.sh: no t2 and t2_before line for each system"; exit 1; } ;;
  threads_every_command)
    run "$AGGLO" "$T/out"
    [ "$(grep -Ec '^  t2 +wall +[0-9.]+ s  CPU +[0-9.]+ s  speed-up [0-9.]+x, CPU [0-9.]+x of t1$' "$log")" = 4 ] ||
      { cat "$log"; echo "FAIL: bench/$name.sh: no t2 line for each of the four smoke commands"; exit 1; } ;;
  dsmc_threads)  # (the before/after variants with this agglo as BEFORE_AGGLO)
    BEFORE_AGGLO=$AGGLO VARIANTS="j1 j2 j1_before j2_before" run "$AGGLO" "$T/out"
    for v in "j2      " "j2_before"; do
      [ "$(grep -Ec "^  $v wall +[0-9.]+ s  user +[0-9.]+ s  wall ([0-9.]+x|-), user ([0-9.]+x|-) of j1(; parallel efficiency [0-9.]+)?$" "$log")" = 2 ] ||
        { cat "$log"; echo "FAIL: bench/$name.sh: no $v line for each case"; exit 1; }
    done ;;
  lammps_compare)
    lammps_singleton
    AGGLO=$AGGLO run "$T/out"
    expect '^ratio agglo / LAMMPS = [0-9.]+  ->  AGREE \(3 % criterion\)$'
    expect '^final KE / KE_0: agglo [0-9.]+, LAMMPS [0-9.]+$' ;;
  mpi_farm)
    run "$AGGLO"
    expect '^\| 2 x 1 \| [0-9.]+ \| 4 \| [0-9.]+ \([0-9.]+-[0-9.]+\) \| [0-9.]+ \| [0-9.]+ \|$' ;;
  partmc_brownian_best_step)
    AGGLO=$AGGLO run "$T/out"
    expect '^after: user mean [0-9.]+ s, range [0-9.]+-[0-9.]+ s; N\(T\) error [-+][0-9.]+ '
    expect '^PartMC best step \(2.6-4.0 s\) / agglo after: [0-9.]+-[0-9.]+x' ;;
  partmc_cases)
    AGGLO=$AGGLO run "$T/out" 2> "$T/stderr.txt" || { cat "$T/stderr.txt"; exit 1; }
    for c in constant additive; do expect "^\| $c \| 1e3 \| [0-9]+ \| ([0-9.]+|–) \|"; done
    expect '^\| brownian \| binned \| 0.36 \|' ;;
  spectral_far_field)
    run "$BUILD"
    expect '^ +2.5 +10 dense/fmm: solve [0-9.]+x, product -?[0-9.]+x$' ;;
  table2_wall_time)
    AGGLO=$AGGLO OUT=$T/out run
    expect '^== calibration [0-9]+ s; calibration \+ Table 2: [0-9]+ s$'
    expect_file "$T/out/table2.json"
    /usr/bin/python3 -c 'import json, sys; r = json.load(open(sys.argv[1]))["rows"]; sys.exit(len(r) != 4)' \
      "$T/out/table2.json" || { echo "FAIL: table2.json has not the 4 rows of Table 2"; exit 1; } ;;
  *)
    echo "FAIL: no smoke invocation for bench/$name.sh in tests/bench/script_smoke.sh"; exit 1 ;;
esac
echo "bench/$name.sh: smoke run passed"
