#include "agglo/run/sweep_seeds.hpp"

#include <string>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/io/netcdf_writer.hpp"
#include "agglo/run/ranks.hpp"
#include "agglo/run/seed_ensemble.hpp"

namespace agglo::run {

std::vector<SweepAxis> with_seed_axis(const Command& cmd, const Config& base, std::vector<SweepAxis> axes,
                                      long long n) {
  if (n < 2)
    throw ConfigError(fmt::format("--seeds {}: a sweep with seeds needs a whole number >= 2 of members per point", n));
  if (!cmd.seed_key())
    throw ConfigError(fmt::format("--seeds: command '{}' has no random seed to vary", cmd.name()));
  const std::string key(cmd.seed_key()->dotted());
  for (const auto& a : axes)
    if (a.key == key)
      throw ConfigError(fmt::format("--seeds {} with --param {}: the seeds are already swept; give one or the other",
                                    n, key));
  SweepAxis seeds{key, {}};
  for (auto s : member_seeds(cmd.seed(base), static_cast<std::size_t>(n))) seeds.values.push_back(std::to_string(s));
  axes.push_back(std::move(seeds));
  return axes;
}

std::vector<io::SweepPoint> sweep_points(const SweepResult& res, std::size_t members) {
  std::vector<io::SweepPoint> points;
  for (std::size_t first = 0; first + members <= res.cases.size(); first += members) {
    const auto& c = res.cases[first];
    io::SweepPoint p{{c.values.begin(), c.values.end() - 1}, c.folder, members, {}};
    p.stats = io::summary_stats({res.summaries.begin() + static_cast<std::ptrdiff_t>(first),
                                 res.summaries.begin() + static_cast<std::ptrdiff_t>(first + members)});
    points.push_back(std::move(p));
  }
  return points;
}

SeededSweep execute_seeded_sweep(const Command& cmd, const Config& base, const std::vector<SweepAxis>& axes,
                                 SweepPlan& plan, const std::filesystem::path& path, const RunContext& ctx,
                                 const nlohmann::json& details) {
  SeededSweep out{execute_sweep(cmd, base, axes, plan, path, ctx, details), {}};
  if (!is_output_rank()) return out;
  out.points = sweep_points(out.runs, axes.back().values.size());
  std::vector<std::string> keys;
  for (std::size_t k = 0; k + 1 < axes.size(); ++k) keys.push_back(axes[k].key);
  const OutputDir folder(path);
  if (ctx.formats.csv) io::write_sweep_points(folder, keys, out.points);
  if (ctx.formats.netcdf) {
    Config resolved = base.clone();
    try {
      cmd.parse(resolved);  // every default filled in, as the sweep's config.resolved.toml
    } catch (const ConfigError&) {
      resolved = base.clone();  // valid only with the swept values: as written
    }
    write_results_nc(folder, resolved, "sweep", cmd.seed(base), io::sweep_points_dataset(keys, out.points),
                     "complete", "sweep_ensemble.nc");
  }
  return out;
}

}  // namespace agglo::run
