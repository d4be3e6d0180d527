#!/usr/bin/env bash
# Showcase part: charged agglomerates (Ruan & Li 2022, sections 2.2-2.3) and a static
# electrostatics solve with surface charge output.
set -euo pipefail
A=build/agglo
echo "== 3. Charged tetrahedron: v_crit at kappa_p = 1 (point charges exact) and histories at 0.18 m/s"
$A -q vcrit cases/seed000_charged_tetrahedron_k1.toml --overwrite --out results/charged_k1-vcrit
$A -q collide cases/seed000_charged_tetrahedron_k1.toml --speed 0.18 --overwrite --out results/charged_k1-0.18
$A -q collide cases/seed000_charged_tetrahedron_k15.toml --speed 0.18 --overwrite --out results/charged_k15-0.18
echo "== 4. Static electrostatics of the charged tetrahedron (spectral solver, surface charge in surface.vtu)"
$A -q electrostatics cases/electrostatics_tetrahedron.toml --overwrite --out results/electrostatics_tetrahedron
