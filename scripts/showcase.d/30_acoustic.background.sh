#!/usr/bin/env bash
# Showcase part: DSMC acoustic agglomeration with droplets (Zhao et al. 2023), the full 4 s baseline of
# seed Fig. 4 (140 dB, 2000 Hz, 30 um droplets at 1000 cm^-3; about 40 s on 2 cores).
set -euo pipefail
A=build/agglo
echo "== 5. Acoustic agglomeration with droplets: 4 s baseline (efficiency, size distributions, snapshots)"
$A -q acoustic cases/seed002_baseline.toml --overwrite --out results/acoustic_baseline
