#!/usr/bin/env bash
# agglo collide --checkpoint / --resume (docs/restart.md, "Collide"): a run killed by the fault hook in the middle
# of its N-th checkpoint write (several N), interrupted by SIGINT, or stopped after it finished, and
# then resumed, leaves every output byte-identical to the uninterrupted run (run.json aside; result.json
# without its wall-time field), including the final checkpoint.bin; neutral and charged (kappa_p = 2.5,
# spectral; 555 solves in 1 s of CPU per run, where kappa_p = 15 took 1252 solves in 3.6 s: the restart of
# the spectral warm start and of the pair-corrected hold is the same code, and ImpactCheckpoint.* restart
# kappa_p = 15), at 1 and 2 threads. A checkpoint of another config is refused with exit 2 and one line.
. "$(dirname "$0")/lib.sh"  # A, SRC, T, fail, AC, NT

CH=$SRC/cases/seed000_charged_tetrahedron_k2p5.toml
NS=(--set time.after_contact=2e-4 --set output.snapshot_interval=5e-5)
CS=(--set time.after_contact=4e-5 --set output.snapshot_interval=2e-5 --set projectile.gap_radii=0.3)

# same DIR_A DIR_B: the same files with the same bytes (run.json aside; result.json without *seconds*)
same() {
  local a=$1 b=$2 f
  (cd "$a" && find . -type f ! -name run.json | sort) > "$T/list_a"
  (cd "$b" && find . -type f ! -name run.json | sort) > "$T/list_b"
  cmp -s "$T/list_a" "$T/list_b" || fail "$a and $b hold different files: $(diff "$T/list_a" "$T/list_b" | tr '\n' ' ')"
  grep -qx ./checkpoint.bin "$T/list_a" || fail "$a has no final checkpoint.bin"
  while read -r f; do
    if [ "$f" = ./result.json ]; then
      /usr/bin/python3 - "$a/$f" "$b/$f" <<'PY' || fail "result.json differs ($a vs $b)"
import json, sys
strip = lambda d: {k: v for k, v in d.items() if "seconds" not in k}
a, b = (strip(json.load(open(p))) for p in sys.argv[1:3])
sys.exit(0 if a == b else 1)
PY
    elif [ "$f" = ./results.nc ]; then  # by content, wall-clock timing variables aside
      /usr/bin/python3 "$SRC/tests/cli/same_results_nc.py" "$a/$f" "$b/$f" || fail "results.nc differs ($a vs $b)"
    else
      cmp -s "$a/$f" "$b/$f" || fail "$f differs ($a vs $b)"
    fi
  done < "$T/list_a"
}

collide() { $A -q --no-plots collide "$@" > "$T/stdout" 2> "$T/stderr"; }
# the same without the shell's report of the fault hook's SIGKILL
collide_quiet() { { collide "$@"; } 2> /dev/null; }

check_case() {  # check_case TAG CASE INTERVAL KILLS [settings...]
  local tag=$1 case=$2 iv=$3 kills=$4; shift 4
  local ref=$T/$tag-ref
  collide "$case" --out "$ref" --threads 2 --checkpoint "$iv" "$@" || fail "$tag: uninterrupted run: $(cat "$T/stderr")"
  collide "$case" --out "$T/$tag-plain" --threads 2 "$@" || fail "$tag: run without checkpoints"
  cp "$ref/checkpoint.bin" "$T/$tag-plain/" && same "$ref" "$T/$tag-plain"  # checkpoints change no output
  local n rc
  for n in $kills; do
    local d=$T/$tag-kill$n
    AGGLO_FAULT_KILL_CHECKPOINT=$n collide_quiet "$case" --out "$d" --threads 1 --checkpoint "$iv" "$@"; rc=$?
    [ $rc -eq 137 ] || fail "$tag: the fault hook must kill checkpoint write $n (exit $rc)"
    ls "$d"/checkpoint.bin.tmp-* > /dev/null 2>&1 || fail "$tag: no half-written checkpoint after kill $n"
    if [ "$n" -gt 1 ]; then [ -f "$d/checkpoint.bin" ] || fail "$tag: kill $n lost the previous checkpoint"; fi
    collide "$case" --out "$d" --threads 2 --checkpoint "$iv" --resume "$@" ||
      fail "$tag: resume after kill $n: $(cat "$T/stderr")"
    same "$ref" "$d"
  done
  # resuming a finished run changes nothing
  collide "$case" --out "$ref" --threads 1 --checkpoint "$iv" --resume "$@" || fail "$tag: resume of a finished run"
  same "$ref" "$T/$tag-kill${kills##* }"
  # another config: refused, one line, exit 2, the folder left as it was (run.json included)
  cp -r "$ref" "$T/$tag-before-refusal"
  collide "$case" --out "$ref" --checkpoint "$iv" --resume "$@" --set material.friction=0.25; rc=$?
  [ $rc -eq 2 ] || fail "$tag: resume with another config must exit 2, got $rc"
  [ "$(wc -l < "$T/stderr")" -eq 1 ] || fail "$tag: the refusal must be one line: $(cat "$T/stderr")"
  grep -q "config hash" "$T/stderr" || fail "$tag: the refusal must name the config hash: $(cat "$T/stderr")"
  diff -r "$T/$tag-before-refusal" "$ref" > /dev/null || fail "$tag: the refused resume changed the folder"
}

check_case neutral "$NT" 5e-5 "1 2 4" "${NS[@]}"
check_case charged "$CH" 2e-5 "2 3" "${CS[@]}"

# SIGINT at an arbitrary step (soon after the first checkpoint of a run of a few seconds): exit 130, a
# checkpoint of the step where the run stopped, resumed identical. Where the run stops depends on the
# machine's load (a signal that arrives while a snapshot or checkpoint is written is met a few steps after
# that output's time), so the checkpoint is identified by what it holds, never by its distance from the
# checkpoint grid: its step is later than the first periodic checkpoint's, and its time lies within one
# results row (1e-4 s) after the last row of the flushed partial results.nc; had the interruption written no
# checkpoint, the file would hold the last periodic one, up to 1e-2 s (100 rows) behind the results.
LONG=(--set time.after_contact=0.5 --set time.early_stop=false --set output.snapshot_interval=5e-2
      --set output.timeseries_interval=1e-4)
ck_step_time() {  # checkpoint header: magic, format, 4 strings, then step and simulated time since launch
  /usr/bin/python3 -c '
import struct, sys
b = open(sys.argv[1], "rb").read()
at = 12
for _ in range(4):
    at += 8 + struct.unpack_from("<Q", b, at)[0]
print(*struct.unpack_from("<Qd", b, at))' "$1"
}
collide "$NT" --out "$T/long-ref" --threads 2 --checkpoint 1e-2 "${LONG[@]}" || fail "long run"
$A -q --no-plots collide "$NT" --out "$T/long" --threads 1 --checkpoint 1e-2 "${LONG[@]}" > /dev/null 2>&1 &
pid=$!
for _ in $(seq 1 400); do [ -f "$T/long/checkpoint.bin" ] && break; sleep 0.02; done
read -r first_step _ <<< "$(ck_step_time "$T/long/checkpoint.bin")"
sleep 0.2
kill -INT $pid; wait $pid; rc=$?
[ $rc -eq 130 ] || fail "SIGINT must give exit 130, got $rc (the run may have ended first)"
/usr/bin/python3 -c 'import netCDF4, sys; d = netCDF4.Dataset(sys.argv[1]); sys.exit(d.getncattr("status") != "incomplete" or len(d.dimensions["time"]) < 1)' \
  "$T/long/results.nc" || fail "SIGINT: results.nc missing, not marked incomplete or empty"
read -r step t <<< "$(ck_step_time "$T/long/checkpoint.bin")"
/usr/bin/python3 -c '
import sys, netCDF4
step, first, t = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])
last = float(netCDF4.Dataset(sys.argv[4])["time"][-1])
sys.exit(0 if step > first and last - 1e-12 <= t < last + 1e-4 else 1)' "$step" "$first_step" "$t" "$T/long/results.nc" ||
  fail "no checkpoint written at the interruption (step $step, t $t s; first periodic checkpoint: step $first_step)"
collide "$NT" --out "$T/long" --threads 2 --checkpoint 1e-2 --resume "${LONG[@]}" || fail "resume after SIGINT"
same "$T/long-ref" "$T/long"
echo "restart_collide: OK"
