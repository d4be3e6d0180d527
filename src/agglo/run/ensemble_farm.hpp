#pragma once
// The MPI task farm of the ensemble runner (docs/scaling.md). Under `mpirun -n K`, the outermost
// run_jobs of every rank comes here with the same job list (the pipeline runs on every rank and the jobs
// of a round are fixed by the configuration). Rank 0 decides which jobs still have to run (its journal),
// runs jobs on its own threads and, on its calling thread, hands the next job index to any rank that asks
// (dynamic load balancing: a job goes to whichever job slot is free first) and journals every result as it
// arrives. Every other rank runs one job slot per thread; a slot's request for the next job carries the
// outcome of its previous one. At the end rank 0 sends all outcomes, in job order, to every rank, so each
// rank continues (e.g. the next bisection round) with the same results as a single process would have.
#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/run/ensemble.hpp"

namespace agglo::run {

// Collective over all ranks (see above); returns the outcomes by job index on every rank.
std::vector<JobOutcome> run_jobs_on_ranks(const std::vector<Job>& jobs, const EnsembleOptions& opt);

// Marks the current thread as running a job while it lives (in_job()).
class JobScope {
 public:
  JobScope();
  ~JobScope();
  JobScope(const JobScope&) = delete;
  JobScope& operator=(const JobScope&) = delete;

 private:
  bool saved_;
};

// Shared with run_jobs (ensemble.cpp): the indices of the jobs the journal does not hold (the others are
// filled into `out`), and one job run into `out` (its error caught; journaled with rank and seconds).
std::vector<std::size_t> pending_jobs(const std::vector<Job>& jobs, const Journal* journal,
                                      std::vector<JobOutcome>& out);
void run_one(const Job& job, std::size_t index, int threads, const EnsembleOptions& opt, JobOutcome& out,
             const std::atomic<std::size_t>* stop_at = nullptr);

// An outcome as JSON and back ({"result", "reused", "seconds", "error": {"type", "message"}}); the error
// keeps its type (InterruptedError, LimitError, ConfigError, NumericalError, else std::runtime_error).
nlohmann::json outcome_to_json(const JobOutcome& o);
JobOutcome outcome_from_json(const nlohmann::json& j);

}  // namespace agglo::run
