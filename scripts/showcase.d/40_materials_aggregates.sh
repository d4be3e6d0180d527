#!/usr/bin/env bash
# Showcase part (issue 24): materials per primary, an aggregate-aggregate impact, and the sticking
# speed of a sphere on a wall by bisection, an aggregate-wall impact (a few seconds on 2 cores).
set -euo pipefail
A=build/agglo
echo "== 6. Mixed materials: a fly-ash sphere hits the silica tetrahedron (docs/model.md §A.8)"
$A -q collide cases/materials_ash_on_silica.toml --overwrite --out results/materials_ash_on_silica
echo "== 7. Aggregate-aggregate impact: two 8-primary BPCA aggregates stick head-on at 0.05 m/s"
$A -q collide cases/aggregate_aggregate.toml --overwrite --out results/aggregate_aggregate
echo "== 8. Sticking speed of a sphere on a wall by bisection (vcrit.criterion = \"sticking\")"
$A -q vcrit cases/sphere_wall.toml --set 'vcrit.criterion="sticking"' --set vcrit.v_min=0.02 --set vcrit.v_max=0.1 \
  --set vcrit.scan_points=5 --set vcrit.tolerance=2e-4 --overwrite --out results/sphere_wall-sticking
echo "== 9. Aggregate-wall impact: the breakage study's 500-primary BPCA aggregate at 0.5 m/s (docs/studies/breakage_wall.md)"
$A -q collide cases/breakage_wall_bpca.toml --overwrite --out results/breakage_wall_bpca
