#pragma once
// Results of an acoustic or sectional run (agglo acoustic, agglo sectional): efficiency.csv, psd.csv,
// snapshots.csv, run.log, summary.json, and results.nc as labelled arrays; a DSMC run (acoustic) adds
// the PM columns to efficiency.csv (and their last values to summary.json) and outcomes_by_pair.csv
// (dim pair_type; docs/outputs.md). Concentrations are given in
// cm-3 (the papers' unit); everything else in SI. The three tables are declared once (acoustic_tables);
// in results.nc their columns keep their CSV names except the times (`time`, `psd_time`,
// `snapshot_time`) and the bin centre (`diameter`, psd.csv's d_mid_m), and add the bin edges
// (`diameter_edge`); summary.json's scalars follow as 0-d variables (nested statistics as
// "<selection>_<key>"), except the series' last values (fine_efficiency, pure_droplet_fraction).
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/acoustics/run.hpp"
#include "agglo/io/dataset.hpp"
#include "agglo/io/output_dir.hpp"
#include "agglo/io/table.hpp"

namespace agglo::writers {

// efficiency.csv (dim time), psd.csv (dims psd_time x diameter), snapshots.csv (dim snapshot_row),
// outcomes_by_pair.csv (dim pair_type; DSMC only).
std::vector<io::Table> acoustic_tables(const acoustics::AcousticObservations& o);

// The scalars of summary.json (also the row of a sweep table and run.json's details).
nlohmann::json acoustic_summary(const acoustics::AcousticObservations& o);

// Writes all five files; run.log only when `tables` is false (--format netcdf: results.nc holds the rest).
void write_acoustic(const OutputDir& out, const acoustics::AcousticObservations& o, bool tables = true);

// results.nc's content: the tables, then summary.json's scalars.
io::Dataset acoustic_dataset(const acoustics::AcousticObservations& o);

}  // namespace agglo::writers
