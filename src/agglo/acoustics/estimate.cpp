#include "agglo/acoustics/estimate.hpp"
#include "agglo/acoustics/initial_placement.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/acoustics/run.hpp"

namespace agglo::acoustics {

namespace {

// Resident bytes per sample: 26 doubles, id, population, cell index and order (samples.hpp,
// engine.hpp), with the slack of the arrays grown sample by sample while sampling.
constexpr double kSampleBytes = 320.0;
// Per cell: statistics, start and fill indices, an error string slot (engine.cpp).
constexpr double kCellBytes = sizeof(CollisionStats) + 2.0 * sizeof(std::uint32_t) + 32.0;
// Text bytes of one row of efficiency.csv, psd.csv and snapshots.csv; run.log, summary.json, plots.
constexpr double kEfficiencyRowBytes = 300.0;  // 207 measured with the 12 PM columns (104 without)
constexpr double kPsdRowBytes = 110.0;
constexpr double kSnapshotRowBytes = 100.0;
constexpr double kSmallFilesBytes = 1024.0 * 1024.0;

std::string key(const settings::Setting& s) { return std::string(s.dotted()); }

}  // namespace

Estimate acoustic_estimate(const AcousticCase& c) {
  const auto& k = settings::acoustic_settings();
  const auto& s = c.engine;
  const double samples = static_cast<double>(sample_count_after_cloning(c));  // [sampling] clones included
  const double steps = std::round(s.t_end / s.collision_dt);
  const double sub = s.motion.integrator == Integrator::none ? 0.0 : std::max(1.0, std::round(s.collision_dt / s.motion_dt));
  const auto& cells = s.motion.domain.cells;
  const double ncells = static_cast<double>(cells[0]) * static_cast<double>(cells[1]) * static_cast<double>(cells[2]);

  const double every = std::max(1.0, std::round(c.output.efficiency_interval / s.collision_dt));
  const double eff_rows = steps / every + 2.0;
  const double psd_rows = static_cast<double>(c.output.psd_times.size()) * c.output.psd_bins;
  const double snap_rows = static_cast<double>(c.output.snapshot_times.size()) * samples * c.output.snapshot_x_fraction;
  const double eff_text = eff_rows * kEfficiencyRowBytes, psd_text = psd_rows * kPsdRowBytes;
  const double snap_text = snap_rows * kSnapshotRowBytes;

  Estimate e;
  add_to(e.steps, steps * samples * (1.0 + sub),
         {key(k.time.end), key(k.time.collision_dt), key(k.population.samples), key(k.sampling.min_samples_per_cell),
          key(k.time.motion_dt)});
  std::vector<std::string> mem_keys{key(k.population.samples), key(k.domain.cells_x), key(k.domain.cells_y),
                                    key(k.domain.cells_z)};
  if (snap_rows > samples) mem_keys.insert(mem_keys.begin(), key(k.output.snapshot_times));
  const double observed = eff_rows * sizeof(EfficiencyRow) + psd_rows * 4.0 * sizeof(double) +
                          snap_rows * sizeof(SnapshotRow);
  add_to(e.memory, samples * kSampleBytes + ncells * kCellBytes + observed + std::max({eff_text, psd_text, snap_text}),
         mem_keys);
  add_to(e.output, eff_text + psd_text + snap_text + kSmallFilesBytes,
         {key(k.output.snapshot_times), key(k.population.samples), key(k.output.efficiency_interval),
          key(k.output.psd_times), key(k.output.psd_bins)});
  return e;
}

}  // namespace agglo::acoustics
