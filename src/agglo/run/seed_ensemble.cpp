#include "agglo/run/seed_ensemble.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/io/dataset_json.hpp"
#include "agglo/io/ensemble_tables.hpp"
#include "agglo/run/journal.hpp"
#include "agglo/run/ranks.hpp"

namespace agglo::run {

namespace {
std::uint64_t mix(std::uint64_t z) {  // SplitMix64 finaliser
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
constexpr std::uint64_t kSeedMask = 0x7fffffffffffffffull;  // the seed key's range 0..INT64_MAX
}  // namespace

std::vector<std::int64_t> member_seeds(std::int64_t base, std::size_t n) {
  std::vector<std::int64_t> seeds;
  for (std::size_t k = 0; k < n; ++k) {
    std::uint64_t s = k == 0 ? static_cast<std::uint64_t>(base) : mix(mix(static_cast<std::uint64_t>(base)) + k) & kSeedMask;
    while (std::find(seeds.begin(), seeds.end(), static_cast<std::int64_t>(s)) != seeds.end()) s = mix(s) & kSeedMask;
    seeds.push_back(static_cast<std::int64_t>(s));
  }
  return seeds;
}

SweepPlan plan_seed_ensemble(const Command& cmd, const Config& base, long long n) {
  if (n < 1)
    throw ConfigError(fmt::format("--seeds {}: the number of ensemble members must be a whole number >= 1", n));
  if (!cmd.seed_key())
    throw ConfigError(fmt::format("--seeds: command '{}' has no random seed to vary", cmd.name()));
  SweepAxis axis{std::string(cmd.seed_key()->dotted()), {}};
  for (auto s : member_seeds(cmd.seed(base), static_cast<std::size_t>(n))) axis.values.push_back(std::to_string(s));
  SweepPlan plan = plan_sweep(cmd, base, {axis});
  plan.keep_data = true;
  plan.journal_key = hash_hex(plan.journal_key + "\nseed ensemble");
  return plan;
}

Estimate seed_ensemble_estimate(const Command& cmd, const SweepPlan& plan, const RunContext& ctx) {
  Estimate total = sweep_estimate(cmd, plan, ctx);
  Config first = plan.configs.front().clone();
  cmd.parse(first);
  RunContext one = ctx;
  one.threads = 1;
  const Estimate e = cmd.estimate(first, one);
  add_to(total.output, 2.0 * output_bytes(e.output.value, ctx.formats), e.output.keys);
  return total;
}

namespace {
// The sweep table of the members (dim `case`) and their exact seeds, next to the statistics.
void add_member_table(io::Dataset& d, const io::Dataset& table, const std::vector<std::int64_t>& seeds) {
  for (const auto& [name, length] : table.dims) d.add_dim(name, length);
  for (const auto& v : table.variables)
    if (!d.find(v.name)) d.variables.push_back(v);
  for (auto it = table.attributes.begin(); it != table.attributes.end(); ++it) d.attributes[it.key()] = it.value();
  d.add_ints("member_seed", {"case"}, "1", "random seed of the member", seeds);
}
}  // namespace

SeedEnsembleResult ensemble_statistics(SweepResult res, const std::vector<std::int64_t>& seeds) {
  std::vector<io::Dataset> members;
  for (std::size_t i = 0; i < res.case_data.size(); ++i) {
    if (res.case_data[i].is_null())
      throw std::invalid_argument(fmt::format("seed ensemble: member {} returned no data", i));
    members.push_back(io::dataset_from_json(res.case_data[i]));
  }
  SeedEnsembleResult out;
  out.summary = io::summary_stats(res.summaries);
  auto data = std::make_shared<io::Dataset>(io::ensemble_dataset(members));
  if (res.data) add_member_table(*data, *res.data, seeds);
  data->attributes["members"] = static_cast<std::int64_t>(seeds.size());
  data->attributes["seeds"] = seeds;
  out.data = data;
  out.seeds = seeds;
  out.members = std::move(res);
  return out;
}

SeedEnsembleResult execute_seed_ensemble(const Command& cmd, const Config& base, SweepPlan& plan,
                                         const std::filesystem::path& path, const RunContext& ctx) {
  check_budgets(seed_ensemble_estimate(cmd, plan, ctx), budgets_of(ctx), base.file());
  std::vector<std::int64_t> seeds;
  std::vector<std::string> values;
  for (const auto& c : plan.cases) {
    values.push_back(c.values.front());
    seeds.push_back(std::stoll(c.values.front()));
  }
  const SweepAxis axis{std::string(cmd.seed_key()->dotted()), values};
  const nlohmann::json details = {{"param", axis.key},          {"values", values},
                                  {"command", std::string(cmd.name())}, {"ensemble", "seeds"},
                                  {"members", plan.cases.size()}, {"seeds", seeds}};
  SweepResult res = execute_sweep(cmd, base, {axis}, plan, path, ctx, details);
  if (!is_output_rank()) return {std::move(res), seeds, {}, nullptr};
  auto ens = ensemble_statistics(std::move(res), seeds);
  const OutputDir out(path);
  if (ctx.formats.csv) {
    io::write_ensemble_summary(out, ens.summary);
    io::write_ensemble_timeseries(out, *ens.data);
  }
  if (ctx.formats.netcdf) {
    Config resolved = base.clone();
    cmd.parse(resolved);
    write_results_nc(out, resolved, cmd.name(), cmd.seed(base), *ens.data);
  }
  return ens;
}

}  // namespace agglo::run
