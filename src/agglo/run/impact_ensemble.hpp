#pragma once
// The impacts of vcrit and breakup as jobs of the ensemble runner: job key "v=<speed> offset=<offset>"
// (17 significant digits), followed by " orientation=<k>/<M>" for rotation k of a set of M > 1
// (breakup.orientations; one orientation keeps the older keys, so older journals stay valid),
// result = result.json of the impact (writers::outcome_json), so a journal entry restores the outcome
// exactly and `--resume` repeats only the missing impacts.
#include "agglo/impact/breakup.hpp"
#include "agglo/impact/vcrit.hpp"
#include "agglo/run/ensemble.hpp"

namespace agglo::run {

// Every impact starts from `relaxed` (one relaxation of the agglomerate serves every speed/offset;
// with several orientations each impact rotates it rigidly about its centroid, exact for the contacts).
// `c` and `relaxed` must outlive the returned functions.
impact::ImpactBatch impact_batch(const impact::ImpactCase& c, const dem::Particles& relaxed, EnsembleOptions opt);
impact::SpeedBatch speed_batch(const impact::ImpactCase& c, const dem::Particles& relaxed, EnsembleOptions opt);

// The journal context of an impact ensemble: the command and the resolved case without the
// sections that only choose the jobs ([vcrit], [breakup]).
std::string impact_context(std::string_view command, const Config& cfg);

// The journal key of one impact job.
std::string impact_job_key(const impact::ImpactJob& job);

}  // namespace agglo::run
