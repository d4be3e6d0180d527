#!/usr/bin/env bash
# The main job: reproduces the headline results of both seed papers on embedded defaults and
# writes CSV/JSON/VTK outputs and PNG plots under results/. A few minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
A=build/agglo
[ -x "$A" ] || bash scripts/setup.sh
mkdir -p results
echo "== 1. Critical break-up velocity of the neutral agglomerates (Ruan & Li 2022, seed value 0.176 m/s)"
$A -q vcrit cases/seed000_neutral_tetrahedron.toml --overwrite --out results/neutral_tetrahedron-vcrit
$A -q vcrit cases/seed000_neutral_square.toml --overwrite --out results/neutral_square-vcrit
echo "== 2. Collision histories just below and above v_crit (time series, VTK snapshots, plots)"
$A -q collide cases/seed000_neutral_tetrahedron.toml --speed 0.17 --overwrite --out results/neutral_tetrahedron-0.170
$A -q collide cases/seed000_neutral_tetrahedron.toml --speed 0.20 --overwrite --out results/neutral_tetrahedron-0.200
# Parts named *.background.sh (the acoustic baseline: two OpenMP threads that spin briefly, then sleep, when waiting) start
# first and run beside the others, which are mostly one thread and plotting; their output is printed
# when they end. Ctrl-C or a failure stops them too.
# Each runs in its own process group (setsid), so that stopping the showcase stops its agglo too.
bg_logs=() bg_pids=()
stop_background() {
  local p
  for p in "${bg_pids[@]}"; do kill -TERM -- "-$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -f "${bg_logs[@]}"
}
trap stop_background EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
for extra in scripts/showcase.d/*.background.sh; do
  [ -e "$extra" ] || continue
  bg_logs+=("$(mktemp)")
  setsid bash "$extra" > "${bg_logs[-1]}" 2>&1 &
  bg_pids+=($!)
done
for extra in scripts/showcase.d/*.sh; do
  case "$extra" in *.background.sh) continue ;; esac
  [ -e "$extra" ] && bash "$extra"
done
for i in "${!bg_pids[@]}"; do
  status=0
  wait "${bg_pids[$i]}" || status=$?
  cat "${bg_logs[$i]}"
  [ "$status" -eq 0 ] || { echo "showcase: a background part failed (exit $status, output above)" >&2; exit "$status"; }
done
echo "== done: see results/ (PNG plots, CSV time series, JSON results, VTK for ParaView)"
