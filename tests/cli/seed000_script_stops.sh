#!/usr/bin/env bash
# scripts/reproduce_seed000.sh runs its steps side by side (four bisections, the fit, the histories). A signal
# to the script, or a step that fails, must stop every step at once: no agglo process may keep running (and
# writing) after the script has ended: it ends only after them. SIGTERM 3 s into a real run: the script ends
# with 143 within 3 s, and none of the agglo processes it started is left. Then a step that fails (a key no case has, given
# to the bisections and histories): the script ends at once with that step's exit 2, the fit stopped with it.
source "$(dirname "$0")/lib.sh"
cd "$SRC" || fail "no source dir"
left() { pgrep -f -- "--out $T/$1/" || true; }

AGGLO=$A OUT=$T/sig bash scripts/reproduce_seed000.sh > "$T/sig.log" 2>&1 &
pid=$!
for _ in $(seq 100); do [ -n "$(left sig)" ] && break; sleep 0.05; done
[ -n "$(left sig)" ] || fail "no step started: $(tail -3 "$T/sig.log")"
sleep 3
kill -TERM $pid
t0=$(date +%s%N)
wait $pid
rc=$?
[ $rc -eq 143 ] || fail "exit $rc after SIGTERM (expected 143): $(tail -3 "$T/sig.log")"
[ $(( ($(date +%s%N) - t0) / 1000000 )) -lt 3000 ] || fail "the script took more than 3 s to stop"
[ -z "$(left sig)" ] || fail "agglo processes left after SIGTERM: $(left sig)"
grep -q "every other step stopped too" "$T/sig.log" || fail "no message: $(tail -3 "$T/sig.log")"

t0=$(date +%s%N)
AGGLO=$A OUT=$T/bad bash scripts/reproduce_seed000.sh --set no_such.key=1 > "$T/bad.log" 2>&1
rc=$?
[ $(( ($(date +%s%N) - t0) / 1000000 )) -lt 5000 ] || fail "the script ran on for more than 5 s after a step failed"
[ $rc -eq 2 ] || fail "exit $rc with a failing step (expected 2): $(tail -3 "$T/bad.log")"
[ -z "$(left bad)" ] || fail "agglo processes left after a failed step: $(left bad)"
grep -q "no_such" "$T/bad.log" || fail "the failing step's error is not shown: $(tail -3 "$T/bad.log")"
echo ok
