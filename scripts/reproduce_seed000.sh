#!/usr/bin/env bash
# Reproduces Ruan & Li (2022) sections 2.2-2.3 (seed Table 2, Figs. 3d, 4d, 5) with the cases in
# cases/: v_crit of the neutral and charged tetrahedra (kappa_p = 1, 2.5, 15), U/U0 and R_g
# histories. Writes results/seed000/{table2.csv,table2.json,*.png}. Extra arguments go to every
# agglo call (e.g. --set electrostatics.update_fraction=0.025).
set -euo pipefail
cd "$(dirname "$0")/.."
A=build/agglo
OUT=results/seed000
mkdir -p "$OUT"
start=$(date +%s)
# The four bisections are independent: they run side by side so that both cores stay busy while
# one bisection round waits for its slowest (unbroken, full-length) run.
pids=()
for k in neutral k1 k2p5 k15; do
  if [ $k = neutral ]; then c=cases/seed000_neutral_tetrahedron.toml; else c=cases/seed000_charged_tetrahedron_$k.toml; fi
  echo "== v_crit $k"
  $A -q --no-plots vcrit "$c" --overwrite --out "$OUT/vcrit_$k" "$@" &
  pids+=($!)
done
for p in "${pids[@]}"; do wait "$p"; done
end=$(date +%s)
echo "== Table 2 wall time: $((end - start)) s"
echo "== histories (seed Figs. 3d, 4d, 5)"
$A -q --no-plots collide cases/seed000_neutral_tetrahedron.toml --speed 0.175 --overwrite --out "$OUT/hist_neutral_0.175" "$@"
for k in k1 k15; do
  $A -q --no-plots collide cases/seed000_charged_tetrahedron_$k.toml --speed 0.18 --overwrite --out "$OUT/hist_${k}_0.18" "$@"
done
/usr/bin/python3 scripts/plot_seed000.py "$OUT" "$((end - start))"
