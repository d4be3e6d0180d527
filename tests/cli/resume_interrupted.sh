#!/usr/bin/env bash
# --resume after an interruption without --checkpoint (issue 23 item 3; docs/restart.md): SIGINT writes a
# checkpoint where the run stops even without --checkpoint, so --resume continues it instead of starting
# again from t = 0 and overwriting what was written; the continued run ends with the uninterrupted run's
# results byte for byte. A folder without checkpoint.bin (a run killed before it) is started again, and
# the run says so on stderr; the earlier results stay until the new run replaces them. A run finished
# without --checkpoint leaves no checkpoint.bin.
source "$(dirname "$0")/lib.sh"
# 0.5 s of simulated time: ≈ 1.5 s of run on a 2-core machine, so that the SIGINT 0.5 s after the start lands
# inside it (0.15 s took 0.54 s in all, and the signal came after the end once the machine was idle).
CASE=(--set time.end=0.5 --set "output.snapshot_times=[0.0,0.01]" --set "output.psd_times=[0.0,0.5]"
      --set output.efficiency_interval=0.001 --set population.0.samples=4500 --set population.1.samples=100)
# (exec: run ... & is then the agglo process itself, which the signals below reach)
run() { exec "$A" -q --no-plots acoustic "$AC" "${CASE[@]}" --threads 2 "$@"; }
FILES=(efficiency.csv psd.csv snapshots.csv)

(run --out "$T/full") > /dev/null 2> "$T/err" || fail "uninterrupted run: $(cat "$T/err")"
[ ! -e "$T/full/checkpoint.bin" ] || fail "checkpoint.bin written by a finished run without --checkpoint"

run --out "$T/int" > /dev/null 2> "$T/err" &
pid=$!
for _ in $(seq 600); do grep -q '"running"' "$T/int/run.json" 2> /dev/null && break; sleep 0.05; done
sleep 0.5
kill -INT $pid 2> /dev/null
wait $pid
rc=$?
[ $rc -eq 130 ] || fail "interrupted run: exit $rc (expected 130; the run may have ended before the signal): $(cat "$T/err")"
[ -f "$T/int/checkpoint.bin" ] || fail "no checkpoint.bin after SIGINT without --checkpoint"
t_int=$(grep -o 'interrupted at t = [0-9.e+-]*' "$T/int/run.log") || fail "run.log not marked incomplete"
rows_int=$(wc -l < "$T/int/efficiency.csv")
(run --out "$T/int" --resume) > /dev/null 2> "$T/err" || fail "resume: $(cat "$T/err")"
[ ! -s "$T/err" ] || fail "resume from a checkpoint printed: $(cat "$T/err")"
for f in "${FILES[@]}"; do cmp -s "$T/full/$f" "$T/int/$f" || fail "resumed $f differs from the uninterrupted run's"; done
echo "ok   SIGINT without --checkpoint ($t_int s, $rows_int rows), --resume continued: identical results"

# No checkpoint (killed before one): the run starts again, says so, and keeps the old files until the end.
run --out "$T/kill" > /dev/null 2>&1 &
pid=$!
for _ in $(seq 600); do grep -q '"running"' "$T/kill/run.json" 2> /dev/null && break; sleep 0.05; done
cp "$T/full/efficiency.csv" "$T/kill/efficiency.csv"  # stands for the results of an earlier piece
kill -KILL $pid
wait $pid 2> /dev/null
run --out "$T/kill" --resume > /dev/null 2> "$T/err" &
pid=$!
for _ in $(seq 600); do grep -q '"running"' "$T/kill/run.json" 2> /dev/null && break; sleep 0.05; done
cmp -s "$T/full/efficiency.csv" "$T/kill/efficiency.csv" || fail "the restarted run removed the earlier results at its start"
wait $pid || fail "restart without a checkpoint: $(cat "$T/err")"
[ "$(wc -l < "$T/err")" -eq 1 ] && grep -q "warning: --resume: .* has no checkpoint.bin .*starts again from the beginning" "$T/err" ||
  fail "restart without a checkpoint not announced in one line: $(cat "$T/err")"
for f in "${FILES[@]}"; do cmp -s "$T/full/$f" "$T/kill/$f" || fail "restarted $f differs"; done
echo "ok   --resume without a checkpoint: announced, earlier files kept until replaced"
echo "PASS resume_interrupted"
