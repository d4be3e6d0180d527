#include "agglo/run/sweep.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/io/dataset_json.hpp"
#include "agglo/io/ensemble_stats.hpp"
#include "agglo/io/sweep_dataset.hpp"
#include "agglo/io/sweep_table.hpp"
#include "agglo/run/ensemble.hpp"
#include "agglo/run/ranks.hpp"

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
                      auto r = execute(cmd, plan.configs[i], root / res.cases[i].folder, sub, extra);
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

namespace {
// The base case with every default filled in, for the sweep folder's config.resolved.toml. A base that
// is valid only with the swept values (e.g. a required key given by --param) is kept as written.
Config resolved_base(const Command& cmd, const Config& base) {
  Config r = base.clone();
  try {
    cmd.parse(r);
    return r;
  } catch (const ConfigError&) {
    return base.clone();
  }
}

// sweep.csv (CSV format) and the table as a dataset (res.data; results.nc in NetCDF format).
void write_sweep_outputs(const OutputDir& out, const Config& resolved, long long seed,
                         const std::vector<SweepAxis>& axes, SweepResult& res, const RunContext& ctx) {
  std::vector<io::SweepRow> rows;
  for (std::size_t i = 0; i < res.cases.size(); ++i)
    rows.push_back({res.cases[i].values, res.cases[i].folder, res.summaries[i]});
  std::vector<std::string> keys;
  for (const auto& x : axes) keys.push_back(x.key);
  if (ctx.formats.csv) io::write_sweep_table(out, keys, rows);
  res.data = std::make_shared<const io::Dataset>(io::sweep_dataset(keys, rows));
  if (ctx.formats.netcdf) write_results_nc(out, resolved, "sweep", seed, *res.data);
}
}  // namespace

SweepResult execute_sweep(const Command& cmd, const Config& base, const std::vector<SweepAxis>& axes,
                          SweepPlan& plan, const std::filesystem::path& path, const RunContext& ctx,
                          const nlohmann::json& details) {
  const auto start = std::chrono::steady_clock::now();
  check_budgets(sweep_estimate(cmd, plan, ctx), budgets_of(ctx), base.file());
  const Config resolved = resolved_base(cmd, base);
  long long seed = 0;  // of the base case; of the first case when the base alone is not valid
  try {
    seed = cmd.seed(base);
  } catch (const ConfigError&) {
    seed = cmd.seed(plan.configs.front());
  }
  const auto folder = claim_run_folder(path, folder_policy(ctx), "sweep");  // rank 0's, or a scratch folder
  const ScratchFolder scratch(folder, path);
  OutputDir out(folder);
  write_run_started(out, "sweep", base.file());
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  SweepResult res;
  plan.cases_root = path;  // under MPI every rank writes the cases it runs there (not into its scratch folder)
  try {
    res = run_sweep(cmd, plan, out, ctx);
  } catch (const std::exception& e) {  // the journal keeps the finished cases; run.json says why it stopped
    const bool stopped = dynamic_cast<const InterruptedError*>(&e) != nullptr;
    write_run_files(out, resolved, "sweep", seed, seconds(), {{stopped ? "interrupted" : "error", e.what()}},
                    stopped ? "incomplete" : "failed");
    throw;
  }
  write_sweep_outputs(out, resolved, seed, axes, res, ctx);
  write_run_files(out, resolved, "sweep", seed, seconds(), details);
  return res;
}

}  // namespace agglo::run
