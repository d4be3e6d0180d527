#include "agglo/run/ensemble.hpp"

#include <algorithm>
#include <atomic>
#include <thread>

#include <omp.h>

#include "agglo/core/error.hpp"

namespace agglo::run {

int resolve_threads(int requested) {
  if (requested > 0) return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

namespace {

// Indices of the jobs to run; the others are filled from the journal.
std::vector<std::size_t> pending_jobs(const std::vector<Job>& jobs, const Journal* journal,
                                      std::vector<JobOutcome>& out) {
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    if (journal) {
      if (auto r = journal->find(jobs[i].key)) {
        out[i].result = std::move(*r);
        out[i].reused = true;
        continue;
      }
    }
    todo.push_back(i);
  }
  return todo;
}

void run_one(const Job& job, std::size_t index, int threads, const EnsembleOptions& opt, JobOutcome& out) {
  try {
    throw_if_cancelled(opt.cancel);
    out.result = job.run(JobContext{index, threads, opt.cancel});
    if (opt.journal) opt.journal->record(job.key, index, out.result);
  } catch (...) {
    out.error = std::current_exception();
  }
}

}  // namespace

std::vector<JobOutcome> run_jobs(const std::vector<Job>& jobs, const EnsembleOptions& opt) {
  std::vector<JobOutcome> out(jobs.size());
  const std::vector<std::size_t> todo = pending_jobs(jobs, opt.journal, out);
  if (todo.empty()) return out;
  const int total = resolve_threads(opt.threads);
  const int workers = std::min<int>(total, static_cast<int>(todo.size()));
  const int per_job = std::max(1, total / workers);
  std::atomic<std::size_t> next{0}, done{jobs.size() - todo.size()};
  auto worker = [&] {
    omp_set_num_threads(per_job);
    for (std::size_t k; (k = next++) < todo.size();) {
      run_one(jobs[todo[k]], todo[k], per_job, opt, out[todo[k]]);
      const double f = static_cast<double>(++done) / static_cast<double>(jobs.size());
      if (opt.reporter) opt.reporter->progress(opt.label, f, 0.0);
    }
  };
  const int saved = omp_get_max_threads();
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(worker);
  worker();  // the calling thread works too
  for (auto& t : pool) t.join();
  omp_set_num_threads(saved);
  return out;
}

void rethrow_first_error(const std::vector<JobOutcome>& outcomes) {
  for (const auto& o : outcomes) {
    if (!o.error) continue;
    try {
      std::rethrow_exception(o.error);
    } catch (const InterruptedError&) {
      throw;
    } catch (...) {
    }
  }
  for (const auto& o : outcomes)
    if (o.error) std::rethrow_exception(o.error);
}

}  // namespace agglo::run
