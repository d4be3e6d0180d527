#include "agglo/run/seed_ensemble.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/io/dataset_json.hpp"
#include "agglo/io/ensemble_stats.hpp"
#include "agglo/io/sweep_dataset.hpp"
#include "agglo/io/sweep_table.hpp"

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

std::vector<SweepAxis> with_seed_axis(const Command& cmd, const Config& base, std::vector<SweepAxis> axes,
                                      long long n) {
  if (n < 2) throw ConfigError(fmt::format("--seeds {}: a seed ensemble needs a whole number >= 2 of members", n));
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

io::Dataset point_dataset(const SweepResult& res, std::size_t first, std::size_t members,
                          const std::vector<std::string>& keys) {
  std::vector<io::Dataset> data;
  std::vector<io::SweepRow> rows;
  std::vector<std::int64_t> seeds;
  for (std::size_t i = first; i < first + members; ++i) {
    if (i >= res.case_data.size() || res.case_data[i].is_null())
      throw std::invalid_argument(fmt::format("seed ensemble: member {} returned no data", i - first));
    data.push_back(io::dataset_from_json(res.case_data[i]));
    rows.push_back({res.cases[i].values, res.cases[i].folder, res.summaries[i]});
    seeds.push_back(std::stoll(res.cases[i].values.back()));
  }
  io::Dataset d = io::ensemble_dataset(data);
  add_member_table(d, io::sweep_dataset(keys, rows), seeds);
  d.attributes["members"] = static_cast<std::int64_t>(members);
  d.attributes["seeds"] = seeds;
  return d;
}

}  // namespace agglo::run
