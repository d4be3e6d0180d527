#!/usr/bin/env bash
# Wall time of the complete seed-000 Table 2 reproduction (4 v_crit bisections with the default
# spectral solver; issue goal <= 10 min on the 2-core machine), followed by the histories of Figs.
# 3d/4d/5. The Table 2 time is printed as "== Table 2 wall time: N s" and written into
# results/seed000/table2.json by the plot script. AGGLO, OUT and SMOKE=1 (the smoke test, ctest -L bench):
# see scripts/reproduce_seed000.sh.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
exec bash "$SRC/scripts/reproduce_seed000.sh" "$@"
