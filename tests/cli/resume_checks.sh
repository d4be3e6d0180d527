#!/usr/bin/env bash
# Inputs that are not what they claim under --resume (issue 23 items 11 and 12): a checkpoint.bin that
# is a symlink to /dev/zero, a FIFO or larger than the memory budget is refused in one line with exit
# 2, at once, without reading it (before: 1.4 GB read, or blocked for ever); `sweep --resume` with other
# --param/--values/--command, or a seed ensemble with other seeds, is refused in one line naming both
# ensembles (before: the case folders of both sweeps were mixed); a seed ensemble may grow. Job keys
# are printed with the shortest round-trip digits ("v=0.3", not "v=0.29999999999999999"); a huge key is
# cut in the error line; acoustic --seeds records its own command.
source "$(dirname "$0")/lib.sh"
SHORT=(--set time.end=0.004 --set "output.snapshot_times=[0]" --set "output.psd_times=[0]"
       --set population.0.samples=300 --set population.1.samples=30)

# refused NAME COMMAND... : exit 2 within 10 s, one line, matching $PATTERN
refused() {
  local name=$1
  shift
  timeout 10 "$@" > /dev/null 2> "$T/err"
  local rc=$?
  [ $rc -eq 2 ] || fail "$name: exit $rc (124: still running after 10 s): $(head -c 300 "$T/err")"
  [ "$(wc -l < "$T/err")" -eq 1 ] || fail "$name: not one line: $(head -c 300 "$T/err")"
  grep -q -- "$PATTERN" "$T/err" || fail "$name: $(head -c 300 "$T/err")"
  echo "ok   $name: $(cut -c 1-150 "$T/err")"
}

"$A" -q --no-plots acoustic "$AC" "${SHORT[@]}" --out "$T/a" --checkpoint 0.002 > /dev/null 2>&1 || fail "acoustic run"
cp "$T/a/checkpoint.bin" "$T/good.bin"
rm "$T/a/checkpoint.bin"
ln -s /dev/zero "$T/a/checkpoint.bin"
PATTERN="checkpoint.bin: a character device, not a checkpoint file" \
  refused "checkpoint -> /dev/zero" "$A" -q acoustic "$AC" "${SHORT[@]}" --out "$T/a" --resume
rm "$T/a/checkpoint.bin"
mkfifo "$T/a/checkpoint.bin"
PATTERN="checkpoint.bin: a FIFO, not a checkpoint file" \
  refused "checkpoint FIFO" "$A" -q acoustic "$AC" "${SHORT[@]}" --out "$T/a" --resume
rm "$T/a/checkpoint.bin"
truncate -s 200M "$T/a/checkpoint.bin"  # sparse: takes no disk space
PATTERN="checkpoint.bin: 209715200 bytes, more than the memory budget" \
  refused "checkpoint over the memory budget" "$A" -q acoustic "$AC" "${SHORT[@]}" --out "$T/a" --resume --max-memory 100M
cp "$T/good.bin" "$T/a/checkpoint.bin"
"$A" -q --no-plots acoustic "$AC" "${SHORT[@]}" --out "$T/a" --resume > /dev/null 2> "$T/err" || fail "resume: $(cat "$T/err")"

# sweep --resume: only the same sweep
SW=(sweep "$NT" --command collide --param projectile.speed)
"$A" -q --no-plots "${SW[@]}" --values 0.1,0.2 --out "$T/s" > /dev/null 2> "$T/err" || fail "sweep: $(cat "$T/err")"
PATTERN="holds the ensemble --command collide --param projectile.speed --values 0.1,0.2 (run.json).*this one is --command collide --param projectile.speed --values 0.1,0.3" \
  refused "sweep --resume, other values" "$A" -q --no-plots "${SW[@]}" --values 0.1,0.3 --out "$T/s" --resume
PATTERN="this one is --command collide --param projectile.offset_radii --values 0.1,0.2" \
  refused "sweep --resume, other param" "$A" -q --no-plots sweep "$NT" --command collide \
  --param projectile.offset_radii --values 0.1,0.2 --out "$T/s" --resume
[ "$(find "$T/s" -maxdepth 1 -name 'case_*' | wc -l)" -eq 2 ] || fail "a refused resume made case folders: $(ls "$T/s")"
"$A" -q --no-plots "${SW[@]}" --values 0.1,0.2 --out "$T/s" --resume > /dev/null 2> "$T/err" || fail "same sweep: $(cat "$T/err")"

# a seed ensemble records its command, may grow, and refuses other seeds
"$A" -q --no-plots acoustic "$AC" "${SHORT[@]}" --seeds 2 --out "$T/e" > /dev/null 2> "$T/err" || fail "seeds: $(cat "$T/err")"
grep -q '^  "command": "acoustic"' "$T/e/run.json" || fail "acoustic --seeds recorded as: $(grep command "$T/e/run.json")"
"$A" -q --no-plots acoustic "$AC" "${SHORT[@]}" --seeds 3 --out "$T/e" --resume > /dev/null 2> "$T/err" ||
  fail "a seed ensemble grown by --resume: $(cat "$T/err")"
PATTERN="holds the ensemble --command acoustic --seeds 3" \
  refused "--seeds --resume with another seed" "$A" -q --no-plots acoustic "$AC" "${SHORT[@]}" --set seed=5 --seeds 3 \
  --out "$T/e" --resume

# job keys: shortest round-trip digits
"$A" -q --no-plots breakup "$NT" --set breakup.speeds=[0.3] --set breakup.samples=1 --out "$T/b" > /dev/null 2> "$T/err" ||
  fail "breakup: $(cat "$T/err")"
grep -q "\"key\":\"v=0.3 offset=" "$T/b/journal.jsonl" || fail "job key not in shortest digits: $(head -c 300 "$T/b/journal.jsonl")"
! grep -qE '[0-9]{12,}' <(grep -o '"key":"[^"]*"' "$T/b/journal.jsonl") || fail "17-digit job keys: $(head -c 300 "$T/b/journal.jsonl")"
echo "ok   job keys: $(grep -o '"key":"[^"]*"' "$T/b/journal.jsonl" | head -1)"

# a huge key is cut to 80 characters and an ellipsis
K=$(head -c 100000 /dev/zero | tr '\0' k)
PATTERN="unknown key '$(head -c 80 /dev/zero | tr '\0' k)…'" \
  refused "100 kB key" "$A" collide "$NT" --dry-run --set "$K=1"
[ "$(wc -c < "$T/err")" -lt 1000 ] || fail "huge key: $(wc -c < "$T/err") bytes of error line"
echo "PASS resume_checks"
