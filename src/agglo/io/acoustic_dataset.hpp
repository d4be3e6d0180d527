#pragma once
// results.nc of `agglo acoustic` and `agglo sectional` as labelled arrays (io/dataset.hpp), the same
// content as efficiency.csv, psd.csv, snapshots.csv and summary.json (concentrations in cm-3 as there):
//   dim time (coordinate `time` [s], efficiency.csv's t_s): n_total_cm3, n_solid_cm3, n_liquid_cm3,
//     n_mixed_cm3, fine_efficiency, pure_droplet_fraction, solid_volume_fraction, liquid_volume_fraction,
//     collisions, subcycled_particle_steps (efficiency.csv's columns);
//   dims psd_time [s], diameter (bin centres d_mid_m [m]), diameter_edge (bin edges [m]): d_lo_m, d_hi_m
//     (diameter) and solid_/liquid_/mixed_/total_dNdlogd_cm3 (psd_time, diameter);
//   dim snapshot_row (snapshots.csv's rows): snapshot_time [s], id, x_m, y_m, z_m, d_m, solid_volume_m3,
//     liquid_volume_m3, weight, phase (0 solid, 1 liquid, 2 mixed);
//   summary.json's scalars as 0-d variables (nested statistics as "<selection>_<key>"), except
//     fine_efficiency and pure_droplet_fraction (the last values of the time series).
#include "agglo/acoustics/run.hpp"
#include "agglo/io/dataset.hpp"

namespace agglo::io {

Dataset acoustic_dataset(const acoustics::AcousticObservations& o);

}  // namespace agglo::io
