#pragma once
// The ensemble runner behind vcrit, breakup and sweep (and later calibrate and MPI): a list of
// independent jobs, fixed by the configuration and never by the number of cores, run on a pool of
// threads. Results are keyed by job index, so they do not depend on scheduling; every job runs even
// when another fails, and each failure is kept with its job; finished jobs go to the journal as they
// finish, and jobs the journal already holds are not run again (--resume). A cancel token stops the
// pool from starting new jobs. Under `mpirun -n K` (K > 1) the outermost run_jobs spreads its jobs over
// the ranks (run/ensemble_farm.hpp); every rank must then call it with the same jobs, and every rank
// gets the same outcomes back.
// With EnsembleOptions::stop_after the jobs are ordered by priority: once a job's result satisfies it, the
// jobs after it are no longer started and those running stop at their next poll (JobContext::superseded);
// every outcome after the first such job is returned `skipped` (no result, no error), whether it ran or
// not, so the outcomes never depend on the thread count (the MPI farm runs them all and drops the same).
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/run/journal.hpp"
#include "agglo/run/reporter.hpp"

namespace agglo::run {

struct JobContext {
  std::size_t index = 0;
  int threads = 1;                    // OpenMP threads this job may use (already set for its thread)
  const CancelToken* cancel = nullptr;
  const std::atomic<std::size_t>* stop_at = nullptr;  // lowest index whose result met stop_after (or null)
  // A job after one that met EnsembleOptions::stop_after: its result is not needed (it may return early).
  bool superseded() const { return stop_at && index > stop_at->load(std::memory_order_relaxed); }
};

struct Job {
  std::string key;  // stable description of the job, e.g. "v=0.18"; its hash keys the journal
  std::function<nlohmann::json(const JobContext&)> run;
};

struct JobOutcome {
  nlohmann::json result;
  std::exception_ptr error;  // null when the job succeeded
  bool reused = false;       // taken from the journal
  bool skipped = false;      // after the first job that met EnsembleOptions::stop_after: not kept
  double seconds = 0.0;      // wall time of the job (0 when reused or failed)
};

struct EnsembleOptions {
  int threads = 0;                  // total threads (0 = all cores)
  Journal* journal = nullptr;       // optional
  const CancelToken* cancel = nullptr;
  Reporter* reporter = nullptr;     // optional: progress of the ensemble
  std::string label = "jobs";
  std::function<bool(const nlohmann::json& result)> stop_after = {};  // optional: see the header comment
};

std::vector<JobOutcome> run_jobs(const std::vector<Job>& jobs, const EnsembleOptions& opt);

// Rethrows the error of the first failed job in index order (InterruptedError first if any job was
// cancelled, so that an interruption is reported as such). With `jobs`, the message is prefixed by
// the failed job's key ("job 'v=0.18 offset=0.05': ...") and says how many jobs failed; the error
// type (ConfigError, NumericalError, InterruptedError) is kept.
void rethrow_first_error(const std::vector<JobOutcome>& outcomes, const std::vector<Job>* jobs = nullptr);

// True on a thread that is running a job of an ensemble (a run_jobs inside a job runs in its process).
bool in_job();

// Total threads to use: `requested` if > 0, else all cores (under mpirun: the cores of this machine
// divided by the ranks on it, at least 1).
int resolve_threads(int requested);

}  // namespace agglo::run
