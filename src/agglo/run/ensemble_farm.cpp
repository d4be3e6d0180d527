#include "agglo/run/ensemble_farm.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

#include <omp.h>

#include "agglo/core/error.hpp"
#include "agglo/mpi/comm.hpp"

namespace agglo::run {

namespace {

constexpr int kTagFarm = 4101;   // slot -> rank 0: {"slot", "outcome"?, "index"?} or {"finished": true}
constexpr int kTagReply = 4200;  // rank 0 -> slot s (tag kTagReply + s): {"index": i or -1, "cancel": bool}
constexpr int kMaxSlots = 20000;

// Messages are CBOR: exact for every double, NaN and infinities included (JSON text would turn NaN into null).
std::string pack(const nlohmann::json& j) {
  const auto bytes = nlohmann::json::to_cbor(j);
  return {bytes.begin(), bytes.end()};
}
nlohmann::json unpack(const std::string& bytes) { return nlohmann::json::from_cbor(bytes); }

template <class E>
std::exception_ptr make_error(const std::string& message) {
  return std::make_exception_ptr(E(message));
}

std::pair<std::string, std::string> describe(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const InterruptedError& e) {
    return {"interrupted", e.what()};
  } catch (const LimitError& e) {
    return {"limit", e.what()};
  } catch (const ConfigError& e) {
    return {"config", e.what()};
  } catch (const NumericalError& e) {
    return {"numerical", e.what()};
  } catch (const std::exception& e) {
    return {"other", e.what()};
  } catch (...) {
    return {"other", "unknown error"};
  }
}

}  // namespace

nlohmann::json outcome_to_json(const JobOutcome& o) {
  nlohmann::json j = {{"result", o.result}, {"reused", o.reused}, {"seconds", o.seconds}};
  if (o.error) {
    const auto [type, message] = describe(o.error);
    j["error"] = {{"type", type}, {"message", message}};
  }
  return j;
}

JobOutcome outcome_from_json(const nlohmann::json& j) {
  JobOutcome o;
  o.result = j.at("result");
  o.reused = j.at("reused").get<bool>();
  o.seconds = j.at("seconds").get<double>();
  if (!j.contains("error")) return o;
  const auto type = j["error"].at("type").get<std::string>();
  const auto message = j["error"].at("message").get<std::string>();
  if (type == "interrupted") o.error = make_error<InterruptedError>(message);
  else if (type == "limit") o.error = make_error<LimitError>(message);
  else if (type == "config") o.error = make_error<ConfigError>(message);
  else if (type == "numerical") o.error = make_error<NumericalError>(message);
  else o.error = make_error<std::runtime_error>(message);
  return o;
}

namespace {

struct Slots {
  int count = 1;     // job slots of this rank
  int per_job = 1;   // OpenMP threads of each
};

Slots slots_for(const EnsembleOptions& opt, std::size_t jobs) {
  const int total = resolve_threads(opt.threads);
  Slots s;
  s.count = std::clamp<int>(static_cast<int>(std::min<std::size_t>(jobs, static_cast<std::size_t>(total))), 1, kMaxSlots);
  s.per_job = std::max(1, total / s.count);
  return s;
}

// Rank 0's view of a round: the job list, what is left to hand out, what has arrived.
struct Round {
  const std::vector<Job>& jobs;
  const EnsembleOptions& opt;
  std::vector<JobOutcome> out;
  std::vector<std::size_t> todo;
  std::atomic<std::size_t> next{0}, done{0};

  Round(const std::vector<Job>& j, const EnsembleOptions& o) : jobs(j), opt(o), out(j.size()) {
    todo = pending_jobs(jobs, opt.journal, out);
    done = jobs.size() - todo.size();
  }
  // The next job index to run, or -1 when all are handed out.
  long long take() {
    const std::size_t k = next++;
    return k < todo.size() ? static_cast<long long>(todo[k]) : -1;
  }
  void finished() {
    const double f = static_cast<double>(++done) / static_cast<double>(std::max<std::size_t>(1, jobs.size()));
    if (opt.reporter) opt.reporter->progress(opt.label, f, 0.0);
  }
};

// An outcome that arrived from another rank: stored, journaled (if it succeeded), counted.
void accept(Round& r, const nlohmann::json& msg, int source) {
  const auto i = msg.at("index").get<std::size_t>();
  r.out[i] = outcome_from_json(msg.at("outcome"));
  if (!r.out[i].error && r.opt.journal)
    r.opt.journal->record(r.jobs[i].key, i, r.out[i].result, {{"rank", source}, {"seconds", r.out[i].seconds}});
  r.finished();
}

// Rank 0's calling thread: answers the slots of the other ranks until every job has arrived and every
// other rank has said it is finished.
void serve(Round& r) {
  int finished_ranks = 0, source = 0, idle = 0;
  std::string bytes;
  while (finished_ranks < mpi::size() - 1 || r.done < r.jobs.size()) {
    if (!mpi::try_receive(kTagFarm, source, bytes)) {
      std::this_thread::sleep_for(std::chrono::microseconds(++idle < 100 ? 20 : 1000));
      continue;
    }
    idle = 0;
    const auto msg = unpack(bytes);
    if (msg.contains("finished")) {
      ++finished_ranks;
      continue;
    }
    if (msg.contains("outcome")) accept(r, msg, source);
    const nlohmann::json reply = {{"index", r.take()}, {"cancel", r.opt.cancel && r.opt.cancel->cancelled()}};
    mpi::send(source, kTagReply + msg.at("slot").get<int>(), pack(reply));
  }
}

std::vector<JobOutcome> run_as_rank0(const std::vector<Job>& jobs, const EnsembleOptions& opt) {
  Round r(jobs, opt);
  const Slots s = slots_for(opt, std::max<std::size_t>(1, r.todo.size()));
  auto worker = [&] {
    const JobScope scope;
    omp_set_num_threads(s.per_job);
    for (long long i; (i = r.take()) >= 0;) {
      run_one(jobs[i], static_cast<std::size_t>(i), s.per_job, opt, r.out[i]);
      r.finished();
    }
  };
  std::vector<std::thread> pool;
  for (int w = 0; w < s.count; ++w) pool.emplace_back(worker);
  serve(r);
  for (auto& t : pool) t.join();
  nlohmann::json all = nlohmann::json::array();
  for (const auto& o : r.out) all.push_back(outcome_to_json(o));
  mpi::broadcast(pack(all));
  return std::move(r.out);
}

// One job slot of a rank other than 0: asks rank 0 for a job, runs it, sends the outcome with the next request.
void run_slot(const std::vector<Job>& jobs, const EnsembleOptions& opt, int slot, int threads) {
  const JobScope scope;
  omp_set_num_threads(threads);
  EnsembleOptions local = opt;
  local.journal = nullptr;  // rank 0 journals
  local.reporter = nullptr;
  nlohmann::json request = {{"slot", slot}};
  for (;;) {
    mpi::send(0, kTagFarm, pack(request));
    const auto reply = unpack(mpi::receive(0, kTagReply + slot));
    const long long i = reply.at("index").get<long long>();
    if (i < 0) return;
    JobOutcome o;
    if (reply.at("cancel").get<bool>()) o.error = make_error<InterruptedError>("interrupted on rank 0");
    else run_one(jobs[static_cast<std::size_t>(i)], static_cast<std::size_t>(i), threads, local, o);
    request = {{"slot", slot}, {"index", i}, {"outcome", outcome_to_json(o)}};
  }
}

std::vector<JobOutcome> run_as_other_rank(const std::vector<Job>& jobs, const EnsembleOptions& opt) {
  const Slots s = slots_for(opt, std::max<std::size_t>(1, jobs.size()));
  std::vector<std::thread> pool;
  for (int w = 1; w < s.count; ++w) pool.emplace_back(run_slot, std::cref(jobs), std::cref(opt), w, s.per_job);
  const int saved = omp_get_max_threads();
  run_slot(jobs, opt, 0, s.per_job);
  for (auto& t : pool) t.join();
  omp_set_num_threads(saved);
  mpi::send(0, kTagFarm, pack(nlohmann::json{{"finished", true}}));
  const auto all = unpack(mpi::broadcast(""));
  std::vector<JobOutcome> out;
  for (const auto& j : all) out.push_back(outcome_from_json(j));
  return out;
}

}  // namespace

std::vector<JobOutcome> run_jobs_on_ranks(const std::vector<Job>& jobs, const EnsembleOptions& opt) {
  return mpi::rank() == 0 ? run_as_rank0(jobs, opt) : run_as_other_rank(jobs, opt);
}

}  // namespace agglo::run
