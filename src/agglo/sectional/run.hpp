#pragma once
// One `agglo sectional` run: the sectional solution (solver.hpp) observed like an acoustic DSMC run,
// so that writers/acoustic.hpp writes the same files with the same columns:
//   efficiency.csv  every output.efficiency_interval and at the end (collision columns 0: no samples)
//   psd.csv         dN/dlog10 d at output.psd_times; each pivot's particles spread evenly in log d over
//                   its section [d_i r^-1/2, d_i r^1/2] (r = d_{i+1}/d_i) and shared among the output bins
//   snapshots.csv   header only (no samples);  summary.json, run.log  as for acoustic.
// The run never prints or writes files.
#include "agglo/acoustics/run.hpp"
#include "agglo/sectional/case_config.hpp"
#include "agglo/sectional/solver.hpp"

namespace agglo::sectional {

// Concentrations of the current state by phase (the case's one phase) [1/m^3, m^3/m^3, kg/m^3].
acoustics::Counts counts(const SectionalSolver& s);
// dN/dlog10 d of the current state on `bins` (index 3 = total, the case's phase the same) [1/m^3].
std::array<std::vector<double>, 4> psd(const SectionalSolver& s, const acoustics::PsdBins& bins);

// Throws NumericalError on a blow-up, InterruptedError when cancelled.
acoustics::AcousticObservations run_sectional(const SectionalCase& c, const acoustics::RunHooks& hooks = {});

}  // namespace agglo::sectional
