#pragma once
// results.nc of the impact commands as labelled arrays (io/dataset.hpp), the same content as their
// CSV/JSON/VTK files:
//   collide  dim time: timeseries.csv's columns (`time` [s] the coordinate, then kinetic_energy,
//            electrostatic_energy, U_over_U0, radius_of_gyration, n_contacts, radius_of_gyration_agglomerate);
//            result.json's scalars as 0-d variables; dim particle: component, fragment index; dim fragment:
//            fragment_* (size, escaping, separation rate, relative kinetic energy, binding); dims frame,
//            particle, xyz: the VTK snapshots (frame_time, position, velocity, angular_velocity, radius,
//            charge, contacts).
//   vcrit    dim run: v, broken, undecided, contact; v_crit, bracket_lo, bracket_hi, rounds.
//   breakup  dim speed: breakup.csv's columns; dim run: run_v, run_offset_radii, run_broken, ...;
//            dim offset: offsets_radii; v10, v50, v90 (NaN when not reached).
#include "agglo/impact/breakup.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/vcrit.hpp"
#include "agglo/io/dataset.hpp"

namespace agglo::io {

// `outcome` null: an interrupted run (time series and snapshots so far only).
Dataset collide_dataset(const impact::Recorder& rec, const impact::ImpactOutcome* outcome);
Dataset vcrit_dataset(const impact::VcritResult& r);
Dataset breakup_dataset(const impact::BreakupResult& r);

}  // namespace agglo::io
