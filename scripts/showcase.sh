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
for extra in scripts/showcase.d/*.sh; do
  [ -e "$extra" ] && bash "$extra"
done
echo "== done: see results/ (PNG plots, CSV time series, JSON results, VTK for ParaView)"
