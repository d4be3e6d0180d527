#!/usr/bin/env bash
# agglo config --list [SECTION]: one line per declared key (key, type, unit, default, range,
# meaning); an unknown section is a one-line error with exit code 2.
# Usage: config_list.sh AGGLO_EXECUTABLE SOURCE_DIR
set -u
A=$1
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

$A config --list vcrit > "$T/vcrit" || fail "config --list vcrit"
head -1 "$T/vcrit" | grep -q '^\[vcrit\] (vcrit, breakup)' || fail "header: $(head -1 "$T/vcrit")"
[ "$(grep -c '^  vcrit\.' "$T/vcrit")" -eq 7 ] || fail "vcrit must list 7 keys: $(cat "$T/vcrit")"
grep -Eq '^  vcrit\.points_per_round +integer +- +2 +\[1, 64\] +speeds tried per bisection round' "$T/vcrit" \
  || fail "points_per_round line: $(grep points_per_round "$T/vcrit")"
grep -Eq '^  vcrit\.v_min +real +m/s +0\.02 +\(0, 1000\] ' "$T/vcrit" || fail "v_min line"

$A config --list population | grep -q '^\[\[population\]\]' || fail "array sections print as [[name]]"
$A config --list top | grep -q '^  seed ' || fail "top-level keys under 'top'"
$A config --list > "$T/all" || fail "config --list"
grep -q '^  electrostatics\.patches_per_sphere .*\[12, 10000000\]' "$T/all" || fail "patches_per_sphere range"
[ "$(grep -c '^  particles\.radius ' "$T/all")" -eq 1 ] || fail "[[particles]] must be declared once"

$A config --list nosuchsection > "$T/out" 2> "$T/err"
[ $? -eq 2 ] || fail "unknown section must exit 2"
[ "$(wc -l < "$T/err")" -eq 1 ] && grep -q "nosuchsection" "$T/err" || fail "unknown section message: $(cat "$T/err")"
echo "ok"
