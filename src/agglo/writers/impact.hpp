#pragma once
// Results of the impact commands: CSV time series, VTK snapshots, result.json, vcrit.json, breakup.csv/json,
// and results.nc as labelled arrays (the same content):
//   collide  dim time: timeseries_table (`time` [s] the coordinate, the CSV's t); result.json's scalars as
//            0-d variables; dim particle: component, fragment index; dim fragment: fragment_* (size,
//            escaping, separation rate, relative kinetic energy, binding); dims frame, particle, xyz: the
//            VTK snapshots (frame_time, position, velocity, angular_velocity, radius, charge, contacts).
//   vcrit    dim run: v, broken, undecided, contact; v_crit, bracket_lo, bracket_hi, rounds.
//   breakup  dim speed: breakup_table (`speed` the coordinate, the CSV's speed_m_s); dim run: run_v,
//            run_offset_radii, run_broken, ...; dim offset: offsets_radii; v10, v50, v90 (NaN when not reached).
#include <nlohmann/json.hpp>

#include "agglo/impact/breakup.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/vcrit.hpp"
#include "agglo/io/dataset.hpp"
#include "agglo/io/output_dir.hpp"
#include "agglo/io/table.hpp"

namespace agglo::writers {

using impact::BreakupResult;
using impact::ImpactOutcome;
using impact::Recorder;
using impact::VcritResult;

// timeseries.csv (dim time): t, kinetic_energy, electrostatic_energy, U_over_U0, radius_of_gyration,
// n_contacts, radius_of_gyration_agglomerate (the original particles only).
io::Table timeseries_table(const Recorder& rec);
void write_timeseries(const OutputDir& out, const Recorder& rec);
// snapshots/particles_NNNN.vtp + particles.pvd
void write_snapshots(const OutputDir& out, const Recorder& rec);
// result.json of one impact; outcome_from_json reads it back exactly (the ensemble journal stores it).
nlohmann::json outcome_json(const ImpactOutcome& o);
ImpactOutcome outcome_from_json(const nlohmann::json& j);
nlohmann::json vcrit_json(const VcritResult& r);
// breakup.csv (dim speed): speed_m_s, runs, broken, undecided, p_break, ci95_lo, ci95_hi.
io::Table breakup_table(const BreakupResult& r);
// breakup.csv and breakup.json: breakup.csv's points plus
// v10/v50/v90 (null if not reached), the offsets and every run's outcome; with breakup.orientations
// > 1 also each run's orientation index and the set ("orientations": direction, roll_rad).
void write_breakup(const OutputDir& out, const BreakupResult& r);

// results.nc. `outcome` null: an interrupted run (time series and snapshots so far only).
io::Dataset collide_dataset(const Recorder& rec, const ImpactOutcome* outcome);
io::Dataset vcrit_dataset(const VcritResult& r);
io::Dataset breakup_dataset(const BreakupResult& r);

}  // namespace agglo::writers
