#!/usr/bin/env bash
# Showcase part: DSMC acoustic agglomeration with droplets (Zhao et al. 2023), baseline case of
# seed Fig. 4 (140 dB, 2000 Hz, 30 um droplets at 1000 cm^-3), first 0.2 s of the 4 s run (droplets scavenge most strongly early).
set -euo pipefail
A=build/agglo
echo "== 5. Acoustic agglomeration with droplets: baseline (efficiency, size distributions, snapshots)"
$A -q acoustic cases/seed002_baseline.toml --out results/acoustic_baseline_0.2s --set time.end=0.2 --set "output.psd_times=[0, 0.1, 0.2]" --set "output.snapshot_times=[0, 0.05, 0.2]"
echo "   (the full 4 s baseline: build/agglo acoustic cases/seed002_baseline.toml, about 4-20 min on 2 cores)"
