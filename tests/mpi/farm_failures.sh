#!/usr/bin/env bash
# Failures under the MPI task farm: (1) a job that fails (a BEM solve allowed one GMRES iteration) is
# reported once with its parameters while the other jobs complete, on 2 and 3 ranks; (2) `kill -9` of a
# rank ends the job (Debian's Open MPI has no fault-tolerant MPI), the journal keeps what arrived, and
# `--resume` on 2 ranks repeats only what is missing and gives the outputs of an uninterrupted single
# process, and no rank's scratch folder is left behind; (3) a failure met by one rank alone ends the job
# instead of leaving the others waiting; (0) first: only a rank started by mpirun loads the MPI library.
# $1 = agglo, $2 = source dir, $3 = mpirun.
. "$(dirname "$0")/lib.sh"

# (0) MPI is loaded only under a launcher (src/agglo/mpi/backend.hpp): a plain run does not map libmpi,
# a rank started by mpirun maps agglo's MPI module and libmpi (positive control of the same trace).
LD_DEBUG=libs "$AGGLO" --version > /dev/null 2> "$TMP/ld_plain.txt" || fail "agglo --version"
grep -q "libc.so" "$TMP/ld_plain.txt" || fail "LD_DEBUG=libs printed no trace"
grep -q "libmpi" "$TMP/ld_plain.txt" && fail "a plain agglo --version loaded the MPI library"
LD_DEBUG=libs run_mpi 1 --version > /dev/null 2> "$TMP/ld_rank.txt" || fail "mpirun -n 1 agglo --version"
grep -q "libagglo_mpi_module" "$TMP/ld_rank.txt" && grep -q "libmpi.so" "$TMP/ld_rank.txt" ||
  fail "a rank started by mpirun did not load agglo's MPI module and libmpi"
echo "ok MPI loaded only under a launcher"

# (1) one failing case of three
for k in 2 3; do
  out="$TMP/fail$k"
  run_mpi $k -q --no-plots sweep cases/electrostatics_two_spheres.toml --command electrostatics \
    --param electrostatics.max_iterations --values 200,1,300 --set 'electrostatics.solver="bem"' --threads 1 \
    --out "$out" > /dev/null 2> "$TMP/fail$k.err"
  rc=$?
  [ $rc -eq 3 ] || fail "failing job on $k ranks: exit $rc, expected 3 (numerical failure)"
  n=$(grep -c "^agglo: numerical failure: job 'electrostatics.max_iterations=1' (1 of 3 jobs failed; the others completed): bem: GMRES did not converge" "$TMP/fail$k.err")
  [ "$n" = 1 ] || fail "failing job on $k ranks: message: $(head -2 "$TMP/fail$k.err")"
  for c in case_00_200 case_02_300; do
    grep -q '"status": "complete"' "$out/$c/run.json" || fail "$k ranks: $c did not complete"
  done
  grep -q '"status": "failed"' "$out/case_01_1/run.json" || fail "$k ranks: the failed case is not marked failed"
  [ "$(wc -l < "$out/journal.jsonl")" = 2 ] || fail "$k ranks: the journal should hold the 2 completed cases"
  grep -q '"status": "failed"' "$out/run.json" || fail "$k ranks: the sweep's run.json is not marked failed"
done
echo "ok failing job"

# (2) kill -9 of one rank, then --resume
BU=(-q --no-plots --set output.snapshot_interval=0 --set time.early_stop=false --set time.after_contact=0.02
    --set 'breakup.speeds=[0.1,0.12,0.14,0.16,0.18,0.2,0.25,0.3,0.35,0.4,0.45,0.5]' --set breakup.samples=2)
NT=cases/seed000_neutral_tetrahedron.toml
"$AGGLO" breakup $NT "${BU[@]}" --threads 2 --out "$TMP/whole" > /dev/null 2>&1 || fail "uninterrupted breakup"
run_mpi 2 breakup $NT "${BU[@]}" --threads 1 --out "$TMP/killed" > /dev/null 2>&1 &
launcher=$!
for _ in $(seq 1 600); do
  [ "$(cat "$TMP/killed/journal.jsonl" 2>/dev/null | wc -l)" -ge 4 ] && break
  sleep 0.05
done
victim=$(own_rank $launcher "$AGGLO")  # a rank of this mpirun, not of a test running beside it
[ -n "$victim" ] || fail "no rank to kill"
kill -9 "$victim"
wait $launcher
rc=$?
[ $rc -ne 0 ] || fail "mpirun should fail after a rank was killed"
kept=$(wc -l < "$TMP/killed/journal.jsonl")
[ "$kept" -ge 4 ] && [ "$kept" -lt 24 ] || fail "the killed run's journal holds $kept of 24 jobs"
run_mpi 2 breakup $NT "${BU[@]}" --threads 1 --out "$TMP/killed" --resume > /dev/null 2>&1 || fail "resume after kill -9"
/usr/bin/python3 - "$TMP/killed/journal.jsonl" "$kept" << 'PY' || fail "resume repeated finished jobs"
import json, sys
lines = []
for l in open(sys.argv[1]):
    try:
        lines.append(json.loads(l))
    except ValueError:  # a line torn by the kill is skipped, as agglo does
        pass
keys = [l["key"] for l in lines]
assert len(set(keys)) == 24, f"{len(set(keys))} distinct jobs, expected 24"
assert len(keys) == 24, f"{len(keys)} journal lines for 24 jobs: some ran twice"
PY
same_outputs "$TMP/whole" "$TMP/killed" || fail "outputs after kill -9 and --resume differ from one process"
no_scratch_left  # the killed rank's scratch folder is removed by the next run on this machine
echo "ok kill -9 and --resume ($kept of 24 jobs kept)"

# (3) a failure met by one rank alone (rank 1 cannot make its scratch folder: its TMPDIR is missing) must
# not leave rank 0 waiting for it: that rank prints why and, AGGLO_MPI_EXIT_TIMEOUT seconds later, ends
# the job (MPI_Abort) with its exit code.
start=$(date +%s)
AGGLO_MPI_EXIT_TIMEOUT=2 timeout 300 "$MPIRUN" -q -n 1 --bind-to none "$AGGLO" breakup $NT "${BU[@]}" --threads 1 \
  --out "$TMP/alone" : -n 1 --bind-to none env TMPDIR="$TMP/missing" "$AGGLO" breakup $NT "${BU[@]}" --threads 1 \
  --out "$TMP/alone" > /dev/null 2> "$TMP/alone.err"
rc=$?
[ $rc -ne 124 ] || fail "a rank that failed alone left the job waiting (killed by timeout after 300 s)"
[ $rc -eq 2 ] || fail "a rank that failed alone: mpirun exit $rc, expected 2; $(head -3 "$TMP/alone.err")"
grep -q "^\[rank 1 of 2\] agglo: error: no folder for temporary files (TMPDIR=$TMP/missing" "$TMP/alone.err" ||
  fail "the failing rank did not say why: $(head -3 "$TMP/alone.err")"
echo "ok a rank failing alone ends the job ($(( $(date +%s) - start )) s)"
