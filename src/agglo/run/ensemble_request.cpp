#include "agglo/run/ensemble_request.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/io/ensemble_tables.hpp"
#include "agglo/io/sweep_dataset.hpp"
#include "agglo/io/sweep_table.hpp"
#include "agglo/run/journal.hpp"
#include "agglo/run/ranks.hpp"
#include "agglo/run/seed_ensemble.hpp"

namespace agglo::run {

nlohmann::json ensemble_details(const std::string& command, const std::vector<SweepAxis>& axes,
                                const std::vector<std::int64_t>& member_seeds) {
  nlohmann::json d = {{"command", command}};
  if (!axes.empty()) {
    nlohmann::json keys = nlohmann::json::array(), lists = nlohmann::json::array();
    for (const auto& a : axes) {
      keys.push_back(a.key);
      std::string joined;
      for (const auto& v : a.values) joined += (joined.empty() ? "" : ",") + v;
      lists.push_back(joined);
    }
    d["param"] = axes.size() == 1 ? keys[0] : keys;
    d["values"] = axes.size() == 1 ? nlohmann::json(axes[0].values) : lists;
  }
  if (!member_seeds.empty()) {
    d["ensemble"] = "seeds";
    d["members"] = member_seeds.size();
    d["seeds"] = member_seeds;
  }
  return d;
}

namespace {

// The request's own refusals, before any case is parsed.
void check_request(const EnsembleRequest& r, const RunContext& ctx) {
  if (r.seeds < 1)
    throw ConfigError(fmt::format("--seeds {}: the number of members per point must be a whole number >= 1 (1: one "
                                  "run per point)", r.seeds));
  if (ctx.checkpoint_interval > 0.0)
    throw ConfigError(fmt::format("--checkpoint {} with {}: checkpoints are for single runs; an ensemble resumes from "
                                  "its journal (--resume repeats the missing runs)", ctx.checkpoint_interval,
                                  r.seeds > 1 ? fmt::format("--seeds {}", r.seeds) : std::string("a sweep")));
}

// Before the runs of a large ensemble are made (each a parsed case held until the end): one run's step
// and output estimates times the number of runs, and the planned cases' memory (each holds its
// config: twice its resolved text and 1 KiB), against the budgets. `acoustic --seeds 1000000000` took
// minutes and gigabytes before it was refused (issue 23 item 10); now it is refused at once. A base
// case valid only with the swept values is left to the full plan.
void check_run_count(const Command& cmd, const EnsembleRequest& r, const RunContext& ctx) {
  double runs = static_cast<double>(r.seeds);
  for (const auto& a : r.axes) runs *= static_cast<double>(std::max<std::size_t>(a.values.size(), 1));
  if (runs < 1000.0) return;  // planned in full within a second
  Config probe = r.base.clone();
  Estimate one;
  try {
    one = plan(cmd, probe, ctx);
  } catch (const LimitError&) {
    throw;
  } catch (const ConfigError&) {
    return;
  }
  std::vector<std::string> count;  // what multiplies the runs
  if (r.seeds > 1) count.push_back("--seeds");
  if (!r.axes.empty()) count.push_back("--values");
  Estimate all;
  add_to(all.steps, 0.0, count);
  add_to(all.steps, one.steps.value * runs, one.steps.keys);
  add_to(all.output, 0.0, count);
  add_to(all.output, one.output.value * runs, one.output.keys);
  add_to(all.memory, one.memory.value + runs * (2.0 * static_cast<double>(probe.resolved_toml().size()) + 1024.0),
         count);
  check_budgets(all, budgets_of(ctx), r.base.file());
}

// The ensemble folder's config.resolved.toml: the base case with every default filled in; the case itself
// when only the seed varies (member 0 is the base, already parsed); as written when only the swept values
// make it valid (e.g. a required key given by --param).
Config resolved_base(const EnsemblePlan& p) {
  if (p.one_point()) return p.sweep.configs.front().clone();
  Config r = p.request.base.clone();
  try {
    parse_case(*p.cmd, r);
    return r;
  } catch (const ConfigError&) {
    return p.request.base.clone();
  }
}

// sweep_estimate plus, with seeds, each point's statistics files (mean and s.e.: at most twice one member's
// output).
Estimate ensemble_estimate(const EnsemblePlan& p, const RunContext& ctx) {
  Estimate total = sweep_estimate(p.sweep, ctx);
  if (p.seeds.empty()) return total;
  for (std::size_t first = 0; first < p.sweep.estimates.size(); first += p.members()) {
    const auto& e = p.sweep.estimates[first].output;
    add_to(total.output, 2.0 * e.value, e.keys);
  }
  return total;
}

}  // namespace

EnsemblePlan plan_ensemble(EnsembleRequest request, const RunContext& ctx) {
  EnsemblePlan p;
  p.cmd = &find_command(request.command);
  check_request(request, ctx);
  check_run_count(*p.cmd, request, ctx);
  p.axes = request.axes;
  if (request.seeds > 1) {
    p.axes = with_seed_axis(*p.cmd, request.base, std::move(p.axes), request.seeds);
    for (const auto& v : p.axes.back().values) p.seeds.push_back(std::stoll(v));
  }
  p.sweep = plan_sweep(*p.cmd, request.base, p.axes, ctx);  // every case parsed once, before anything is made
  if (!p.seeds.empty()) {
    p.sweep.keep_data = true;
    p.sweep.journal_key = hash_hex(p.sweep.journal_key + "\nseed ensemble");  // never a plain sweep's journal
  }
  p.request = std::move(request);
  p.resolved = resolved_base(p);
  try {
    p.seed = p.cmd->seed(p.request.base);
  } catch (const ConfigError&) {
    p.seed = p.cmd->seed(p.sweep.configs.front());
  }
  p.recorded = p.one_point() ? std::string(p.cmd->name()) : std::string("sweep");
  p.details = ensemble_details(p.request.command, p.request.axes, p.seeds);
  p.estimate = ensemble_estimate(p, ctx);
  return p;
}

namespace {

std::vector<std::string> keys_of(const std::vector<SweepAxis>& axes, std::size_t count) {
  std::vector<std::string> keys;
  for (std::size_t k = 0; k < count; ++k) keys.push_back(axes[k].key);
  return keys;
}

// sweep.csv (CSV format) and the runs' table as a dataset (results.nc in NetCDF format, unless the folder's
// results.nc holds a seed ensemble's statistics).
void write_runs(const EnsemblePlan& p, const OutputDir& out, SweepResult& runs, const RunContext& ctx) {
  std::vector<io::SweepRow> rows;
  for (std::size_t i = 0; i < runs.cases.size(); ++i)
    rows.push_back({runs.cases[i].values, runs.cases[i].folder, runs.summaries[i]});
  const auto keys = keys_of(p.axes, p.axes.size());
  if (ctx.formats.csv) io::write_sweep_table(out, keys, rows);
  runs.data = std::make_shared<const io::Dataset>(io::sweep_dataset(keys, rows));
  if (ctx.formats.netcdf && !p.one_point()) write_results_nc(out, p.resolved, "sweep", p.seed, *runs.data);
}

// Each point's statistics files (in its folder), then the table of the points (with axes).
void write_points(const EnsemblePlan& p, const OutputDir& out, EnsembleResult& res, const RunContext& ctx) {
  const std::size_t n = p.members();
  res.points = sweep_points(res.runs, n);
  const auto keys = keys_of(p.axes, p.axes.size());
  for (std::size_t k = 0; k < res.points.size(); ++k) {
    const std::string name = p.one_point() ? "" : grid_folder("point", k, res.points[k].values);
    auto data = std::make_shared<const io::Dataset>(point_dataset(res.runs, k * n, n, keys));
    for (std::size_t i = k * n; i < (k + 1) * n; ++i) res.runs.case_data[i] = nullptr;  // folded into `data`
    const OutputDir dir = name.empty() ? out : OutputDir(out.path() / name);
    if (ctx.formats.csv) {
      io::write_ensemble_summary(dir, res.points[k].stats);
      io::write_ensemble_timeseries(dir, *data);
    }
    if (ctx.formats.netcdf) write_results_nc(dir, p.sweep.configs[k * n], p.cmd->name(), p.seed, *data);
    if (name.empty()) res.data = data;
    res.point_folders.push_back(name);
  }
  if (p.one_point()) return;
  const auto user_keys = keys_of(p.axes, p.request.axes.size());
  if (ctx.formats.csv) io::write_sweep_points(out, user_keys, res.points);
  if (ctx.formats.netcdf)
    write_results_nc(out, p.resolved, "sweep", p.seed, io::sweep_points_dataset(user_keys, res.points), "complete",
                     "sweep_ensemble.nc");
}

}  // namespace

namespace {

// "--param K --values V" (each axis), "--command C", "--seeds N" of an ensemble's details (run.json).
std::string describe_ensemble(const nlohmann::json& d) {
  std::string s = fmt::format("--command {}", d.value("command", std::string("?")));
  auto text = [](const nlohmann::json& v) {
    if (v.is_string()) return v.get<std::string>();
    std::string joined;
    for (const auto& x : v) {
      if (!joined.empty()) joined += ',';
      joined += x.is_string() ? x.get<std::string>() : x.dump();
    }
    return joined;
  };
  if (d.contains("param")) {
    const bool grid = d["param"].is_array();
    for (std::size_t k = 0; k < (grid ? d["param"].size() : 1); ++k)
      s += fmt::format(" --param {} --values {}", text(grid ? d["param"][k] : d["param"]),
                       grid ? text(d["values"][k]) : text(d["values"]));
  }
  if (d.contains("members")) s += fmt::format(" --seeds {} (seeds {})", d["members"].dump(), text(d["seeds"]));
  return cut_for_message(s);
}

// Under --resume: the folder's ensemble (its run.json details, written at the start) must be this one;
// another --param, --values, --command or --seeds would mix the case folders of two ensembles
// (issue 23 item 11). A folder of an older agglo, whose run.json has no details, is not checked.
void check_same_ensemble(const EnsemblePlan& p, const std::filesystem::path& folder) {
  std::ifstream in(folder / "run.json");
  if (!in) return;
  const auto j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("details") || !j["details"].contains("command")) return;
  nlohmann::json had = nlohmann::json::object();
  for (const char* k : {"command", "param", "values", "ensemble", "members", "seeds"})
    if (j["details"].contains(k)) had[k] = j["details"][k];
  // A seed ensemble without axes may grow (--seeds 4 after --seeds 3): member k keeps its seed and folder.
  const bool grows = !had.contains("param") && !p.details.contains("param") && had.contains("seeds") &&
                     p.details.contains("seeds") && had["seeds"].size() <= p.details["seeds"].size() &&
                     std::equal(had["seeds"].begin(), had["seeds"].end(), p.details["seeds"].begin());
  if (had != p.details && !grows)
    throw ConfigError(fmt::format("output folder {}: holds the ensemble {} (run.json); --resume continues only the same "
                                  "ensemble, this one is {}; give the same options, or choose another --out",
                                  folder.string(), describe_ensemble(had), describe_ensemble(p.details)));
}

}  // namespace

EnsembleResult execute_ensemble(EnsemblePlan& p, const RunContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  const auto& base = p.request.base;
  check_budgets(p.estimate, budgets_of(ctx), base.file());
  const auto& path = p.request.folder;
  if (ctx.resume) check_same_ensemble(p, path);
  const auto folder = claim_run_folder(path, folder_policy(ctx), p.recorded);  // rank 0's, or a scratch folder
  const ScratchFolder scratch(folder, path);
  const OutputDir out(folder);
  write_run_started(out, p.recorded, base.file(), p.details);
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  EnsembleResult res;
  p.sweep.cases_root = path;  // under MPI every rank writes the cases it runs there (not into its scratch folder)
  try {
    res.runs = run_sweep(*p.cmd, p.sweep, out, ctx);
    write_runs(p, out, res.runs, ctx);
    res.data = res.runs.data;
    if (!p.seeds.empty() && is_output_rank()) write_points(p, out, res, ctx);
    write_run_files(out, p.resolved, p.recorded, p.seed, seconds(), p.details);
  } catch (const std::exception& e) {  // the journal keeps the finished runs; run.json says why it stopped
    const bool stopped = dynamic_cast<const InterruptedError*>(&e) != nullptr;
    nlohmann::json details = p.details;  // kept for the check of a later --resume
    details[stopped ? "interrupted" : "error"] = e.what();
    write_stopped_run_files(out, p.resolved, p.recorded, p.seed, seconds(), details,
                            stopped ? "incomplete" : "failed");
    throw;
  }
  return res;
}

EnsembleResult execute_ensemble(EnsembleRequest request, const RunContext& ctx) {
  auto plan = plan_ensemble(std::move(request), ctx);
  return execute_ensemble(plan, ctx);
}

}  // namespace agglo::run
