#include "agglo/run/sweep.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/io/dataset_json.hpp"
#include "agglo/io/ensemble_stats.hpp"
#include "agglo/run/ensemble.hpp"

namespace agglo::run {

std::vector<std::string> split_values(const std::string& list) {
  std::vector<std::string> v;
  for (std::size_t b = 0;;) {
    const auto comma = list.find(',', b);
    const std::string cur = list.substr(b, comma == std::string::npos ? std::string::npos : comma - b);
    const auto first = cur.find_first_not_of(" \t"), last = cur.find_last_not_of(" \t");
    if (first == std::string::npos) throw ConfigError(fmt::format("--values '{}': empty entry", list));
    v.push_back(cur.substr(first, last - first + 1));
    if (comma == std::string::npos) return v;
    b = comma + 1;
  }
}

std::string grid_folder(std::string_view prefix, std::size_t index, const std::vector<std::string>& values) {
  std::string s = fmt::format("{}_{:02d}", prefix, index);
  for (const auto& value : values) {
    s += '_';
    for (char c : value) s += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+') ? c : '_';
  }
  return s;
}

std::vector<SweepCase> sweep_grid(const std::vector<SweepAxis>& axes) {
  if (axes.empty()) throw ConfigError("--param: a config key is required (e.g. population.1.diameter)");
  std::size_t n = 1;
  for (const auto& a : axes) {
    if (std::all_of(a.key.begin(), a.key.end(), [](unsigned char c) { return std::isspace(c) != 0; }))
      throw ConfigError("--param: a config key is required (e.g. population.1.diameter)");
    if (a.values.empty()) throw ConfigError(fmt::format("--values for '{}': at least one value is required", a.key));
    if (std::count_if(axes.begin(), axes.end(), [&](const SweepAxis& b) { return b.key == a.key; }) > 1)
      throw ConfigError(fmt::format("--param '{}' is given more than once (each key is one axis of the grid)", a.key));
    n *= a.values.size();
  }
  std::vector<SweepCase> cases(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t rest = i;
    cases[i].index = i;
    cases[i].values.resize(axes.size());
    for (std::size_t k = axes.size(); k-- > 0;) {
      cases[i].values[k] = axes[k].values[rest % axes[k].values.size()];
      rest /= axes[k].values.size();
    }
    for (std::size_t k = 0; k < axes.size(); ++k) cases[i].assignments.push_back(axes[k].key + "=" + cases[i].values[k]);
    cases[i].folder = grid_folder("case", i, cases[i].values);
  }
  return cases;
}

namespace {
std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}
}  // namespace

SweepPlan plan_sweep(const Command& cmd, const Config& base, const std::vector<SweepAxis>& axes,
                     const RunContext& ctx) {
  SweepPlan plan;
  plan.cases = sweep_grid(axes);
  RunContext one;  // each case's estimate on one thread (sweep_estimate adds up those that run at a time)
  one.threads = 1;
  one.budgets = ctx.budgets;
  one.formats = ctx.formats;
  for (const auto& c : plan.cases) {
    Config cfg = base.clone();
    for (const auto& a : c.assignments) cfg.apply_override(a);
    plan.estimates.push_back(run::plan(cmd, cfg, one));  // parsed once: every case validated before anything runs
    plan.configs.push_back(std::move(cfg));
  }
  plan.journal_key = hash_hex(std::string(cmd.name()) + "\n" + base.resolved_toml());
  return plan;
}

Estimate sweep_estimate(const SweepPlan& plan, const RunContext& ctx) {
  Estimate total;
  std::vector<double> memory;
  for (const auto& e : plan.estimates) {
    add_to(total.steps, e.steps.value, e.steps.keys);
    add_to(total.output, e.output.value, e.output.keys);
    add_to(total.memory, 0.0, e.memory.keys);
    memory.push_back(e.memory.value - kProcessBaseBytes);  // the case's own (results.nc arrays included)
  }
  std::sort(memory.rbegin(), memory.rend());
  memory.resize(std::min(memory.size(), static_cast<std::size_t>(std::max(1, ctx.thread_count()))));
  for (double m : memory) total.memory.value += m;
  total.memory.value += kProcessBaseBytes;
  return total;
}

SweepResult run_sweep(const Command& cmd, SweepPlan& plan, const OutputDir& out, const RunContext& ctx) {
  SweepResult res;
  res.cases = plan.cases;
  const auto root = plan.cases_root.empty() ? out.path() : plan.cases_root;  // where the case folders go
  std::vector<Job> jobs;
  for (std::size_t i = 0; i < res.cases.size(); ++i)
    jobs.push_back({joined(res.cases[i].assignments), [&, i](const JobContext& jc) {
                      RunContext sub = ctx;  // owns its case folders: overwrite
                      sub.reporter = nullptr;
                      sub.cancel = jc.cancel;
                      sub.threads = jc.threads;
                      sub.overwrite = true;
                      nlohmann::json extra = {{"sweep_assignment", joined(res.cases[i].assignments)}};
                      auto r = execute_planned(cmd, plan.configs[i], plan.estimates[i], root / res.cases[i].folder,
                                               sub, extra);
                      if (!plan.keep_data) return r.summary;
                      return nlohmann::json{{"summary", std::move(r.summary)},
                                            {"data", r.data ? io::dataset_to_json(io::labelled_part(*r.data))
                                                            : nlohmann::json()}};
                    }});
  Journal journal(out.file("journal.jsonl"), plan.journal_key, ctx.resume);
  const auto outcomes = run_jobs(jobs, {ctx.threads, &journal, ctx.cancel, &ctx.report(), "sweep"});
  rethrow_first_error(outcomes, &jobs);
  for (const auto& o : outcomes) {
    if (!plan.keep_data) {
      res.summaries.push_back(o.result);
      continue;
    }
    if (!o.result.is_object() || !o.result.contains("summary") || !o.result.contains("data"))
      throw ConfigError(fmt::format("{}: a journal entry is not a seed-ensemble result; run again without --resume",
                                    out.file("journal.jsonl").string()));
    res.summaries.push_back(o.result["summary"]);
    res.case_data.push_back(o.result["data"]);
  }
  return res;
}

}  // namespace agglo::run
