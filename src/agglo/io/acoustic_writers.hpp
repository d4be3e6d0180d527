#pragma once
// Files of an acoustic run (agglo acoustic): efficiency.csv, psd.csv, snapshots.csv, run.log,
// summary.json. Concentrations are written in 1/cm^3 (the papers' unit); everything else in SI.
#include <nlohmann/json.hpp>

#include "agglo/acoustics/run.hpp"
#include "agglo/io/output_dir.hpp"

namespace agglo::io {

// The scalars of summary.json (also the row of a sweep table and run.json's details).
nlohmann::json acoustic_summary(const acoustics::AcousticObservations& o);

// Writes all five files; run.log only when `tables` is false (--format netcdf: results.nc holds the rest).
void write_acoustic(const OutputDir& out, const acoustics::AcousticObservations& o, bool tables = true);

}  // namespace agglo::io
