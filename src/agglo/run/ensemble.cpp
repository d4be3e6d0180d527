#include "agglo/run/ensemble.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

#include <fmt/format.h>
#include <omp.h>

#include "agglo/core/error.hpp"
#include "agglo/mpi/comm.hpp"
#include "agglo/run/ensemble_farm.hpp"

namespace agglo::run {

int resolve_threads(int requested) {
  if (requested > 0) return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / mpi::local_size());
}

namespace {
thread_local bool t_in_job = false;
}  // namespace

bool in_job() { return t_in_job; }

JobScope::JobScope() : saved_(t_in_job) { t_in_job = true; }
JobScope::~JobScope() { t_in_job = saved_; }

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

void run_one(const Job& job, std::size_t index, int threads, const EnsembleOptions& opt, JobOutcome& out,
             const std::atomic<std::size_t>* stop_at) {
  const auto start = std::chrono::steady_clock::now();
  const JobContext ctx{index, threads, opt.cancel, stop_at};
  try {
    const CancelScope cancel_scope(opt.cancel);  // the engines of the job poll it (core/cancel.hpp)
    throw_if_cancelled(opt.cancel);
    out.result = job.run(ctx);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (opt.journal) opt.journal->record(job.key, index, out.result, {{"rank", mpi::rank()}, {"seconds", out.seconds}});
  } catch (...) {
    out.error = std::current_exception();
  }
  if (out.error && ctx.superseded() && !(opt.cancel && opt.cancel->cancelled())) {  // stopped: not needed
    out.error = nullptr;
    out.skipped = true;
  }
}

namespace {

// Lowers `stop_at` to `index` when the job's result meets opt.stop_after.
void note_stop(const EnsembleOptions& opt, std::size_t index, const JobOutcome& o, std::atomic<std::size_t>& stop_at) {
  if (!opt.stop_after || o.error || o.skipped || !opt.stop_after(o.result)) return;
  std::size_t cur = stop_at.load();
  while (index < cur && !stop_at.compare_exchange_weak(cur, index)) {
  }
}

// The first job, in order, whose result meets opt.stop_after (out.size() without one).
std::size_t first_stop(const EnsembleOptions& opt, const std::vector<JobOutcome>& out) {
  for (std::size_t i = 0; i < out.size(); ++i)
    if (opt.stop_after && !out[i].error && !out[i].skipped && opt.stop_after(out[i].result)) return i;
  return out.size();
}

// Marks every outcome after `stop` skipped, its result or error dropped: what a batch returns then never
// depends on which of the jobs after its stop happened to run (threads, ranks).
void drop_after(std::vector<JobOutcome>& out, std::size_t stop) {
  for (std::size_t j = stop + 1; j < out.size(); ++j) {
    out[j] = JobOutcome();
    out[j].skipped = true;
  }
}

// Runs the `todo` jobs on the pool of threads, highest priority (lowest index) first; stop_at as above.
void run_pool(const std::vector<Job>& jobs, const std::vector<std::size_t>& todo, const EnsembleOptions& opt,
              std::vector<JobOutcome>& out, std::atomic<std::size_t>& stop_at) {
  const int total = resolve_threads(opt.threads);
  const int workers = std::min<int>(total, static_cast<int>(todo.size()));
  const int per_job = std::max(1, total / workers);
  std::atomic<std::size_t> next{0}, done{jobs.size() - todo.size()};
  auto worker = [&] {
    const JobScope scope;  // a run_jobs inside these jobs stays in this process
    omp_set_num_threads(per_job);
    for (std::size_t k; (k = next++) < todo.size();) {
      const std::size_t i = todo[k];
      if (i > stop_at.load()) out[i].skipped = true;
      else run_one(jobs[i], i, per_job, opt, out[i], &stop_at);
      note_stop(opt, i, out[i], stop_at);
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
}

}  // namespace

std::vector<JobOutcome> run_jobs(const std::vector<Job>& jobs, const EnsembleOptions& opt) {
  if (mpi::size() > 1 && !in_job()) {  // the ranks run every job; the same ones are kept
    auto out = run_jobs_on_ranks(jobs, opt);
    drop_after(out, first_stop(opt, out));
    return out;
  }
  std::vector<JobOutcome> out(jobs.size());
  const std::vector<std::size_t> todo = pending_jobs(jobs, opt.journal, out);
  // stop_at: the lowest index whose result met stop_after so far. Every job below it has run, so at the end
  // it is the first such job in order.
  std::atomic<std::size_t> stop_at{jobs.size()};
  for (std::size_t i = 0; i < jobs.size(); ++i)
    if (out[i].reused) note_stop(opt, i, out[i], stop_at);
  if (!todo.empty()) run_pool(jobs, todo, opt, out, stop_at);
  drop_after(out, stop_at.load());
  return out;
}

namespace {

template <class E>
[[noreturn]] void throw_with(const E&, const std::string& message) {
  throw E(message);
}

// Rethrows `error` with `prefix` before its message, keeping the error type.
[[noreturn]] void rethrow_prefixed(const std::exception_ptr& error, const std::string& prefix) {
  try {
    std::rethrow_exception(error);
  } catch (const InterruptedError& e) {
    throw_with(e, prefix + e.what());
  } catch (const OutputError& e) {  // before its base class: a full disk marks the folder failed
    throw_with(e, prefix + e.what());
  } catch (const ConfigError& e) {
    throw_with(e, prefix + e.what());
  } catch (const InvalidRunError& e) {  // before its base class
    throw_with(e, prefix + e.what());
  } catch (const NumericalError& e) {
    throw_with(e, prefix + e.what());
  } catch (const std::exception& e) {
    throw std::runtime_error(prefix + e.what());
  }
}

bool is_interruption(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const InterruptedError&) {
    return true;
  } catch (...) {
    return false;
  }
}

}  // namespace

void rethrow_first_error(const std::vector<JobOutcome>& outcomes, const std::vector<Job>* jobs) {
  std::size_t failed = 0, first = outcomes.size();
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    if (!outcomes[i].error) continue;
    ++failed;
    if (first == outcomes.size() || (is_interruption(outcomes[i].error) && !is_interruption(outcomes[first].error)))
      first = i;
  }
  if (failed == 0) return;
  const auto& error = outcomes[first].error;
  if (!jobs || is_interruption(error) || (*jobs)[first].key.empty()) std::rethrow_exception(error);
  std::string more;
  if (failed == outcomes.size() && failed > 1) more = fmt::format(" (all {} jobs failed)", failed);
  else if (outcomes.size() > 1) more = fmt::format(" ({} of {} jobs failed; the others completed)", failed, outcomes.size());
  rethrow_prefixed(error, fmt::format("job '{}'{}: ", (*jobs)[first].key, more));
}

}  // namespace agglo::run
