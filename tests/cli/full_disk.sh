#!/usr/bin/env bash
# A full disk (issue 23 item 8; docs/limits.md, "Output folders"): every command writing into a small
# tmpfs that fills up at some file (a checkpoint, a snapshot, a CSV, surface.vtu, results.nc, run.json
# itself) ends with exit 2 and one line "cannot write FILE: No space left on device", run.json says
# "failed", and no *.tmp-PID file is left. Before: exit 1 "internal error: error while writing", run.json
# left at "running", temporary files left, and SIGSEGV (exit 139) inside HDF5 after a failed
# results.nc write. Needs root for mount: skipped (exit 77) where a tmpfs cannot be mounted.
source "$(dirname "$0")/lib.sh"
FS="$T/fs"
mkdir -p "$FS"
mount -t tmpfs -o size=16k tmpfs "$FS" 2> /dev/null || { echo "SKIP: cannot mount a tmpfs (not root?)"; exit 77; }
trap 'umount "$FS" 2> /dev/null; chmod -R u+w "$T" 2> /dev/null; rm -rf "$T"' EXIT
umount "$FS"

# full SIZE NAME COMMAND CASE [ARGS...]: runs into a fresh tmpfs of SIZE and checks the end.
full() {
  local size=$1 name=$2
  shift 2
  mount -t tmpfs -o "size=$size" tmpfs "$FS" || fail "mount"
  "$A" -q --no-plots "$@" --out "$FS/run" > /dev/null 2> "$T/err"
  local rc=$?
  local tmps
  tmps=$(find "$FS" -name '*.tmp-*')
  local status
  status=$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["status"])' "$FS/run/run.json" 2>&1)
  umount "$FS"
  [ $rc -eq 2 ] || fail "$name ($size): exit $rc, expected 2: $(cat "$T/err")"
  [ "$(wc -l < "$T/err")" -eq 1 ] || fail "$name ($size): not one line: $(cat "$T/err")"
  grep -q "^agglo: error: .*cannot write .*: No space left on device" "$T/err" || fail "$name ($size): $(cat "$T/err")"
  [ -z "$tmps" ] || fail "$name ($size): temporary files left: $tmps"
  [ "$status" = failed ] || fail "$name ($size): run.json status $status"
  echo "ok   $name ($size): $(cut -c 1-110 "$T/err")"
}

# collide --checkpoint: full at the checkpoint, at a snapshot, at results.nc (refused before HDF5 writes:
# less free space than it may need) and, CSV only, at run.json itself (the sizes found on Debian 12
# x86_64; elsewhere another file may be the one that fills the disk)
for size in 16k 48k 64k; do full $size collide collide "$NT" --checkpoint 1e-4; done
full 64k collide-csv collide "$NT" --checkpoint 1e-4 --format csv
full 24k vcrit vcrit "$NT"
full 100k electrostatics electrostatics "$SRC/cases/electrostatics_tetrahedron.toml"
full 100k sectional sectional "$SRC/cases/partmc_brownian.toml"
full 24k sweep sweep "$NT" --command collide --param projectile.speed --values 0.1,0.2
SHORT=(--set time.end=0.02 --set "output.snapshot_times=[0]" --set "output.psd_times=[0]")
full 100k acoustic acoustic "$AC" "${SHORT[@]}" --checkpoint 0.005
echo "PASS full_disk"
