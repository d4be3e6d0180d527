#!/usr/bin/env bash
# A progress line during the pre-impact relaxation (issue 23 item 1): on a terminal, a collide of the
# 30-sphere charged list agglomerate with the BEM solver (kappa_p = 3.8) shows "relaxation ..." within a
# few seconds, while the first electrostatic solve runs (it takes tens of seconds; the relaxation
# reported every 50 steps, so the terminal stayed silent until the run ended or was killed). The run is
# given a pseudo-terminal by script(1) (util-linux; the test is skipped, exit 77, without it) and is
# stopped with SIGINT once the line is seen. Without a terminal (-q or a pipe) nothing is printed.
# $1 = agglo executable, $2 = source dir.
source "$(dirname "$0")/lib.sh"
command -v script > /dev/null || { echo "skipped: script(1) is missing"; exit 77; }
{
  printf 'name = "esp30"\n[agglomerate]\nshape = "list"\nradius = 10e-6\n[electrostatics]\nsolver = "bem"\n\n'
  /usr/bin/python3 "$SRC/tests/cli/list_cluster.py" 30 3.8
} > "$T/bem.toml"

script -q -c "exec $A collide $T/bem.toml --out $T/run --threads 1 --no-plots" /dev/null > "$T/tty" 2>&1 &
pid=$!
seen=0
for _ in $(seq 200); do  # at most 20 s; the first line is due 2 s after the relaxation starts
  if tr '\r' '\n' < "$T/tty" | grep -q "^relaxation "; then seen=1; break; fi
  kill -0 $pid 2> /dev/null || break
  sleep 0.1
done
pkill -INT -P $pid 2> /dev/null  # the agglo run under script's pty (only this script's own child)
wait $pid 2> /dev/null
[ $seen -eq 1 ] || fail "no relaxation progress line within 20 s: $(tr '\r' '\n' < "$T/tty" | tail -3)"
line=$(tr '\r' '\n' < "$T/tty" | grep "^relaxation " | head -1)
[[ "$line" =~ ^relaxation\ +[0-9.]+%\ +([0-9]+\ s\ so\ far|t=.*ETA) ]] || fail "progress line: '$line'"
echo "ok   relaxation progress: '$line'"

# No terminal: no progress line on stderr (only the usual output).
timeout 3 "$A" collide "$T/bem.toml" --out "$T/quiet" --threads 1 --no-plots > /dev/null 2> "$T/err"
! grep -q "relaxation" "$T/err" || fail "a progress line without a terminal: $(head -c 300 "$T/err")"
echo "relaxation_progress: ok"
