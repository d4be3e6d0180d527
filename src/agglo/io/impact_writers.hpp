#pragma once
// Files of the impact experiment: CSV time series, VTK snapshots, result.json, vcrit.json, breakup.csv/json.
#include <nlohmann/json.hpp>

#include "agglo/impact/breakup.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/vcrit.hpp"
#include "agglo/io/output_dir.hpp"

namespace agglo::io {

using impact::BreakupResult;
using impact::ImpactOutcome;
using impact::Recorder;
using impact::VcritResult;

// timeseries.csv: t,kinetic_energy,electrostatic_energy,U_over_U0,radius_of_gyration,n_contacts,
//                 radius_of_gyration_agglomerate (the original particles only)
void write_timeseries(const OutputDir& out, const Recorder& rec);
// snapshots/particles_NNNN.vtp + particles.pvd
void write_snapshots(const OutputDir& out, const Recorder& rec);
// result.json of one impact; outcome_from_json reads it back exactly (the ensemble journal stores it).
nlohmann::json outcome_json(const ImpactOutcome& o);
ImpactOutcome outcome_from_json(const nlohmann::json& j);
nlohmann::json vcrit_json(const VcritResult& r);
// breakup.csv: speed_m_s,runs,broken,undecided,p_break,ci95_lo,ci95_hi; breakup.json: the same plus
// v10/v50/v90 (null if not reached), the offsets and every run's outcome; with breakup.orientations
// > 1 also each run's orientation index and the set ("orientations": direction, roll_rad).
void write_breakup(const OutputDir& out, const BreakupResult& r);

}  // namespace agglo::io
