#!/usr/bin/env bash
# agglo's OpenMP threads spin briefly and then sleep unless the user chose (issue 27 item 3;
# docs/acoustics.md §5.2): libgomp spins a few ms in every wait by default, which on a shared machine made
# --threads 2 slower than --threads 1, and sleeping at once cost a wake-up at every barrier.
# apps/agglo/omp_wait/omp_wait.cpp sets GOMP_SPINCOUNT=1000 before libgomp reads it; this checks, through
# libgomp's own report of its settings (OMP_DISPLAY_ENV=verbose), that the loader ran it in time, and that
# a user's OMP_WAIT_POLICY or GOMP_SPINCOUNT is kept.
source "$(dirname "$0")/lib.sh"

# spincount [ENV...]: the GOMP_SPINCOUNT libgomp reports for `agglo --version` under the given variables
spincount() {
  env "$@" OMP_DISPLAY_ENV=verbose "$A" --version 2>&1 >/dev/null | sed -n "s/^ *GOMP_SPINCOUNT = '\([0-9]*\)'.*/\1/p"
}
s=$(spincount -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT)
if [ -z "$s" ]; then echo "SKIP: the OpenMP runtime is not libgomp (no GOMP_SPINCOUNT in OMP_DISPLAY_ENV)"; exit 77; fi
[ "$s" = 1000 ] || fail "default spin count $s, expected 1000 (short spin): apps/agglo/omp_wait missing or initialised after libgomp"
s=$(spincount -u GOMP_SPINCOUNT OMP_WAIT_POLICY=passive)
[ "$s" = 0 ] || fail "OMP_WAIT_POLICY=passive not kept (spin count $s)"
s=$(spincount -u GOMP_SPINCOUNT OMP_WAIT_POLICY=active)
[ "$s" != 0 ] && [ "$s" -gt 1000000 ] || fail "OMP_WAIT_POLICY=active not kept (spin count $s)"
s=$(spincount -u OMP_WAIT_POLICY GOMP_SPINCOUNT=1234)
[ "$s" = 1234 ] || fail "GOMP_SPINCOUNT=1234 not kept (spin count $s)"
echo "PASS"
