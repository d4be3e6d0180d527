#!/usr/bin/env bash
# Checkpoint and exact restart of `agglo acoustic` (docs/restart.md): runs killed in the middle of a
# checkpoint write (fault hook AGGLO_FAULT_KILL_CHECKPOINT=N) or interrupted by SIGINT, then continued
# with --resume, end with every output equal to the uninterrupted run's (run.json and wall times aside)
# and the same final checkpoint.bin byte for byte, whatever the thread count; a kill during a write
# leaves the previous checkpoint usable; a checkpoint of another config is refused with one line, exit 2.
# $1 = agglo executable, $2 = source dir.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, AC, NT
# 400 collision steps of 5e-5 s, 4600 samples (above the engine's threshold for threads); checkpoints every
# 80 steps (5 of them, the last at the end).
SHORT=(--set time.end=0.02 --set "output.snapshot_times=[0.0,0.01]" --set "output.psd_times=[0.0,0.0101,0.02]"
       --set output.efficiency_interval=0.001 --set output.plots=false --set population.0.samples=4500
       --set population.1.samples=100)
CK=(--checkpoint 0.004)
run() { "$A" -q --no-plots acoustic "$AC" "${SHORT[@]}" "$@"; }

# Every file of folder $1 equals that of $2: run.json skipped, wall times blanked, results.nc by content.
same_outputs() {
  local a=$1 b=$2 f n
  for f in "$a"/* "$b"/*; do
    n=$(basename "$f")
    case "$n" in
      run.json) ;;
      run.log) diff <(sed 's/wall_time=[0-9.]* s/wall_time=X/' "$a/$n") \
                    <(sed 's/wall_time=[0-9.]* s/wall_time=X/' "$b/$n") > /dev/null || { echo "$n differs"; return 1; } ;;
      summary.json) /usr/bin/python3 - "$a/$n" "$b/$n" <<'EOF' || { echo "$n differs"; return 1; } ;;
import json, sys
x, y = (json.load(open(p)) for p in sys.argv[1:])
for d in (x, y):
    d.pop("wall_time_s", None)
sys.exit(0 if x == y else 1)
EOF
      results.nc) /usr/bin/python3 "$SRC/tests/cli/same_results_nc.py" "$a/$n" "$b/$n" || return 1 ;;
      *) cmp -s "$a/$n" "$b/$n" || { echo "$n differs"; return 1; } ;;
    esac
  done
}

# The uninterrupted run, and one without checkpoints (same outputs, no checkpoint.bin).
run --out "$T/full" --threads 2 "${CK[@]}" > /dev/null 2> "$T/err" || fail "uninterrupted run: $(cat "$T/err")"
[ -f "$T/full/checkpoint.bin" ] || fail "no checkpoint.bin after a run with --checkpoint"
run --out "$T/plain" --threads 2 > /dev/null 2>&1 || fail "run without --checkpoint"
[ -e "$T/plain/checkpoint.bin" ] && fail "checkpoint.bin written without --checkpoint"
cp "$T/full/checkpoint.bin" "$T/plain/checkpoint.bin"
same_outputs "$T/full" "$T/plain" || fail "--checkpoint changed the outputs"
echo "ok   uninterrupted run with --checkpoint: $(stat -c %s "$T/full/checkpoint.bin") bytes of checkpoint"

# Killed in the middle of checkpoint write N: the folder keeps checkpoint N-1 (none for N = 1) and a
# partial temporary file; --resume (on 1 or 2 threads) continues from it to the same outputs.
for N in 1 3 5; do
  d="$T/kill$N"
  AGGLO_FAULT_KILL_CHECKPOINT=$N run --out "$d" --threads 2 "${CK[@]}" > /dev/null 2>&1; rc=$?
  [ $rc -eq 137 ] || fail "kill at checkpoint $N: exit $rc (expected 137, SIGKILL)"
  ls "$d"/checkpoint.bin.tmp-* > /dev/null 2>&1 || fail "kill at checkpoint $N: no partial temporary file"
  if [ $N -eq 1 ]; then
    [ -e "$d/checkpoint.bin" ] && fail "kill at the first checkpoint left a checkpoint.bin"
  else
    cmp -s <(head -c 8 "$d/checkpoint.bin") <(printf AGGLOCKP) || fail "kill at checkpoint $N: previous one unreadable"
  fi
  threads=$((N / 2 % 2 + 1))
  run --out "$d" --threads $threads "${CK[@]}" --resume > /dev/null 2> "$T/err" || fail "resume after kill $N: $(cat "$T/err")"
  ls "$d"/checkpoint.bin.tmp-* > /dev/null 2>&1 && fail "resume after kill $N kept the stale temporary file"
  same_outputs "$T/full" "$d" || fail "resume after kill at checkpoint $N ($threads threads) differs"
  echo "ok   killed during checkpoint write $N, resumed on $threads thread(s): identical"
done

# Interrupted by SIGINT once the first checkpoint is on disk (a longer run): the interrupt writes a
# checkpoint, flushes the partial outputs (status incomplete, exit 130); --resume completes it.
LONG=(--set time.end=0.06 --set "output.psd_times=[0.0,0.06]")
"$A" -q --no-plots acoustic "$AC" "${SHORT[@]}" "${LONG[@]}" --out "$T/long" --threads 2 --checkpoint 0.002 \
  > /dev/null 2>&1 || fail "long uninterrupted run"
"$A" -q --no-plots acoustic "$AC" "${SHORT[@]}" "${LONG[@]}" --out "$T/int" --threads 2 --checkpoint 0.002 \
  > /dev/null 2>&1 &
pid=$!
for _ in $(seq 1 600); do [ -f "$T/int/checkpoint.bin" ] && break; sleep 0.05; done
kill -INT $pid 2> /dev/null
wait $pid; rc=$?
status=$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["status"])' "$T/int/run.json")
if [ $rc -eq 130 ]; then
  [ "$status" = incomplete ] || fail "SIGINT: status $status"
  grep -q "^incomplete: interrupted" "$T/int/run.log" || fail "SIGINT: run.log not marked incomplete"
  /usr/bin/python3 -c 'import netCDF4, sys; d = netCDF4.Dataset(sys.argv[1]); sys.exit(d.getncattr("status") != "incomplete" or len(d.dimensions["time"]) < 1)' \
    "$T/int/results.nc" || fail "SIGINT: results.nc missing, not marked incomplete or empty"
  echo "ok   SIGINT at $(grep -o 'interrupted at t = [^)]*)' "$T/int/run.log")"
else
  [ $rc -eq 0 ] || fail "SIGINT'd run: exit $rc"
  echo "note SIGINT arrived after the end of the run"
fi
"$A" -q --no-plots acoustic "$AC" "${SHORT[@]}" "${LONG[@]}" --out "$T/int" --threads 1 --checkpoint 0.002 --resume \
  > /dev/null 2> "$T/err" || fail "resume after SIGINT: $(cat "$T/err")"
same_outputs "$T/long" "$T/int" || fail "resume after SIGINT differs"
echo "ok   interrupted by SIGINT, resumed on 1 thread: identical"

# Resuming a finished run's folder changes nothing.
run --out "$T/full" --threads 1 "${CK[@]}" --resume > /dev/null 2>&1 || fail "resume of a finished run"
same_outputs "$T/full" "$T/kill3" || fail "resume of a finished run changed it"

# A checkpoint of another config, of another format or corrupted: one line, exit 2, the folder kept.
cp -r "$T/kill5" "$T/other"
run --out "$T/other" --resume --set sound.level_db=141 > /dev/null 2> "$T/err"; rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < "$T/err")" -eq 1 ] && grep -q "checkpoint.bin.*config hash.*cannot be resumed" "$T/err" \
  || fail "resume with another config: exit $rc: $(cat "$T/err")"
echo "ok   other config refused: $(cat "$T/err")"
printf '\x07' | dd of="$T/other/checkpoint.bin" bs=1 seek=40 conv=notrunc 2> /dev/null  # in the header strings
run --out "$T/other" --resume > /dev/null 2> "$T/err"; rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < "$T/err")" -eq 1 ] && grep -q "checksum mismatch" "$T/err" \
  || fail "corrupted checkpoint: exit $rc: $(cat "$T/err")"
echo "ok   corrupted checkpoint refused: $(cat "$T/err")"
# Another format version with a valid checksum (FNV-1a 64 over the bytes before it: offset basis
# 14695981039346656037), and a format-1 file (summed with the basis a digit short that format 1 used):
# both refused by their format number, before the checksum.
for fmt in 99:14695981039346656037 1:1469598103934665603; do
  /usr/bin/python3 - "$T/kill3/checkpoint.bin" "$T/other/checkpoint.bin" "${fmt%%:*}" "${fmt##*:}" <<'EOF'
import struct, sys
b = bytearray(open(sys.argv[1], "rb").read()[:-8])
b[8:12] = struct.pack("<I", int(sys.argv[3]))
h = int(sys.argv[4])
for c in b:
    h = ((h ^ c) * 1099511628211) % 2**64
open(sys.argv[2], "wb").write(bytes(b) + struct.pack("<Q", h))
EOF
  run --out "$T/other" --resume > /dev/null 2> "$T/err"; rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l < "$T/err")" -eq 1 ] && grep -q "format version ${fmt%%:*}, this run has format version 2" "$T/err" \
    || fail "checkpoint of format ${fmt%%:*}: exit $rc: $(cat "$T/err")"
  echo "ok   format ${fmt%%:*} refused: $(cat "$T/err")"
done
# The checksum is FNV-1a 64 with its real offset basis: recomputed here over a valid checkpoint.
/usr/bin/python3 - "$T/kill3/checkpoint.bin" <<'EOF' || fail "the checkpoint's checksum is not FNV-1a 64"
import struct, sys
b = open(sys.argv[1], "rb").read()
h = 14695981039346656037
for c in b[:-8]:
    h = ((h ^ c) * 1099511628211) % 2**64
sys.exit(0 if struct.unpack("<Q", b[-8:])[0] == h else 1)
EOF
echo "all restart checks passed"
