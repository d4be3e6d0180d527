#include "agglo/run/sweep.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
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

namespace {
std::string folder_name(std::size_t index, const std::vector<std::string>& values) {
  std::string s = fmt::format("case_{:02d}", index);
  for (const auto& value : values) {
    s += '_';
    for (char c : value) s += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+') ? c : '_';
  }
  return s;
}
}  // namespace

std::vector<SweepCase> sweep_grid(const std::vector<SweepAxis>& axes) {
  if (axes.empty()) throw ConfigError("--param: a config key is required (e.g. population.1.diameter)");
  std::size_t n = 1;
  for (const auto& a : axes) {
    if (std::all_of(a.key.begin(), a.key.end(), [](unsigned char c) { return std::isspace(c) != 0; }))
      throw ConfigError("--param: a config key is required (e.g. population.1.diameter)");
    if (a.values.empty()) throw ConfigError(fmt::format("--values for '{}': at least one value is required", a.key));
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
    cases[i].folder = folder_name(i, cases[i].values);
  }
  return cases;
}

namespace {
Config case_config(const Command& cmd, const Config& base, const SweepCase& c) {
  Config cfg = base.clone();
  for (const auto& a : c.assignments) cfg.apply_override(a);
  Config probe = cfg.clone();
  cmd.parse(probe);  // every case validated before anything runs
  return cfg;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}
}  // namespace

SweepPlan plan_sweep(const Command& cmd, const Config& base, const std::vector<SweepAxis>& axes) {
  SweepPlan plan;
  plan.cases = sweep_grid(axes);
  for (const auto& c : plan.cases) plan.configs.push_back(case_config(cmd, base, c));
  plan.journal_key = hash_hex(std::string(cmd.name()) + "\n" + base.resolved_toml());
  return plan;
}

Estimate sweep_estimate(const Command& cmd, const SweepPlan& plan, const RunContext& ctx) {
  Estimate total;
  std::vector<double> memory;
  RunContext one;
  one.threads = 1;
  one.budgets = ctx.budgets;
  for (const auto& c : plan.configs) {
    Config cfg = c.clone();
    cmd.parse(cfg);
    const Estimate e = cmd.estimate(cfg, one);
    add_to(total.steps, e.steps.value, e.steps.keys);
    add_to(total.output, output_bytes(e.output.value, ctx.formats), e.output.keys);
    add_to(total.memory, 0.0, e.memory.keys);
    memory.push_back(e.memory.value + (ctx.formats.netcdf ? e.output.value : 0.0));  // + the results.nc arrays
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
  std::vector<Job> jobs;
  for (std::size_t i = 0; i < res.cases.size(); ++i)
    jobs.push_back({joined(res.cases[i].assignments), [&, i](const JobContext& jc) {
                      RunContext sub = ctx;  // owns its case folders: overwrite
                      sub.reporter = nullptr;
                      sub.cancel = jc.cancel;
                      sub.threads = jc.threads;
                      sub.overwrite = true;
                      nlohmann::json extra = {{"sweep_assignment", joined(res.cases[i].assignments)}};
                      return execute(cmd, plan.configs[i], out.path() / res.cases[i].folder, sub, extra).summary;
                    }});
  Journal journal(out.file("journal.jsonl"), plan.journal_key, ctx.resume);
  const auto outcomes = run_jobs(jobs, {ctx.threads, &journal, ctx.cancel, &ctx.report(), "sweep"});
  rethrow_first_error(outcomes, &jobs);
  for (const auto& o : outcomes) res.summaries.push_back(o.result);
  return res;
}

}  // namespace agglo::run
