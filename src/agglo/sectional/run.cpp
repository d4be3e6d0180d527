#include "agglo/sectional/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "agglo/acoustics/checkpoint.hpp"
#include "agglo/core/error.hpp"
#include "agglo/sectional/checkpoint.hpp"

namespace agglo::sectional {

namespace {
using acoustics::AcousticObservations;

// Output times: every efficiency interval, the psd times and the end, sorted and unique.
std::vector<double> output_times(const acoustics::AcousticCase& c) {
  const double te = c.engine.t_end, dt = c.output.efficiency_interval;
  std::vector<double> t = c.output.psd_times;
  const auto rows = static_cast<long long>(std::floor(te / dt * (1.0 + 1e-12)));
  for (long long k = 0; k <= rows; ++k) t.push_back(std::min(te, static_cast<double>(k) * dt));
  t.push_back(te);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end(), [&](double a, double b) { return b - a <= 1e-9 * te; }), t.end());
  return t;
}

bool listed(const std::vector<double>& times, double t, double te) {
  return std::any_of(times.begin(), times.end(), [&](double x) { return std::abs(x - t) <= 1e-9 * te; });
}

bool efficiency_due(double t, const acoustics::AcousticCase& c) {
  const double k = t / c.output.efficiency_interval;
  return std::abs(k - std::round(k)) <= 1e-9 * std::max(1.0, k) || t >= c.engine.t_end;
}

std::string parameters_log(const SectionalCase& c, const SectionalSolver& s) {
  const auto& e = c.base.engine;
  const auto& pr = s.initial();
  std::string log = fmt::format("agglo sectional: case {}\n", c.base.file);
  log += fmt::format("gas: T={:g} K P={:g} Pa mu_g={:.6g} Pa s lambda_g={:.6g} m; kernel={}\n", e.motion.gas.temperature,
                     e.motion.gas.pressure, e.motion.gas.viscosity, e.motion.gas.mean_free_path,
                     e.kernel.model);
  log += fmt::format("grid: {} pivots, d = {:.6g} .. {:.6g} m, {} per decade (volume ratio {:.6g}); tolerance {:g}\n",
                     s.grid().size(), s.grid().d.front(), s.grid().d.back(), c.grid.bins_per_decade,
                     std::pow(s.grid().ratio_d, 3), c.grid.tolerance);
  log += fmt::format("initial: N = {:.8g} 1/m^3, volume = {:.8g} m^3/m^3; below the first pivot N = {:.3g}, "
                     "V = {:.3g}; above the last N = {:.3g}, V = {:.3g} (numbers kept at the end pivots)\n",
                     s.number(), s.volume(), pr.below.number, pr.below.volume, pr.above.number, pr.above.volume);
  return log;
}

std::string closing_log(const AcousticObservations& o, const SectionalSolver& s) {
  const auto& st = s.stats();
  const double v0 = o.initial.solid_volume + o.initial.liquid_volume, v1 = o.final.solid_volume + o.final.liquid_volume;
  return fmt::format("steps: accepted={} rejected={} h_min={:.4g} s h_max={:.4g} s\n"
                     "conservation: volume fraction {:.17g} -> {:.17g} (rel. {:.3g}); mass {:.17g} -> {:.17g}\n"
                     "result: N = {:.8g} -> {:.8g} 1/m^3 (N/N0 = {:.8g}) wall_time={:.3f} s\n",
                     st.accepted, st.rejected, st.h_min, st.h_max, v0, v1, v0 > 0 ? v1 / v0 - 1 : 0.0, o.initial.mass,
                     o.final.mass, o.initial.n_total, o.final.n_total,
                     o.initial.n_total > 0 ? o.final.n_total / o.initial.n_total : 0.0, o.wall_time_s);
}

acoustics::EfficiencyRow efficiency_row(double t, const acoustics::Counts& c, const acoustics::Counts& c0) {
  acoustics::EfficiencyRow r;
  r.t = t;
  r.counts = c;
  const double nf0 = c0.n_phase[0], nl0 = c0.n_phase[1];
  r.fine_efficiency = nf0 > 0 ? (nf0 - c.n_phase[0]) / nf0 : 0.0;
  r.pure_droplet_fraction = nl0 > 0 ? c.n_phase[1] / nl0 : 0.0;
  return r;
}
}  // namespace

acoustics::Counts counts(const SectionalSolver& s) {
  acoustics::Counts c;
  c.n_total = s.number();
  c.n_phase[static_cast<int>(s.phase())] = c.n_total;
  (s.phase() == acoustics::Phase::solid ? c.solid_volume : c.liquid_volume) = s.volume();
  c.mass = s.density() * s.volume();
  c.live_samples = static_cast<std::size_t>(std::count_if(s.n().begin(), s.n().end(), [](double v) { return v > 0; }));
  return c;
}

std::array<std::vector<double>, 4> psd(const SectionalSolver& s, const acoustics::PsdBins& bins) {
  const std::size_t K = bins.edges.size() - 1;
  std::array<std::vector<double>, 4> out;
  for (auto& v : out) v.assign(K, 0.0);
  const double half = 0.5 * std::log10(s.grid().ratio_d);
  for (std::size_t i = 0; i < s.n().size(); ++i) {
    const double lo = std::log10(s.grid().d[i]) - half, hi = lo + 2.0 * half;
    for (std::size_t b = 0; b < K; ++b) {
      const double overlap = std::min(hi, std::log10(bins.edges[b + 1])) - std::max(lo, std::log10(bins.edges[b]));
      if (overlap > 0.0) out[3][b] += s.n()[i] * overlap / (2.0 * half);
    }
  }
  for (std::size_t b = 0; b < K; ++b) out[3][b] /= std::log10(bins.edges[b + 1] / bins.edges[b]);
  out[static_cast<int>(s.phase())] = out[3];
  return out;
}

namespace {
// The start: the initial state, or the state and observations of the checkpoint being resumed.
void start(const SectionalCase& c, SectionalSolver& s, AcousticObservations& obs, const acoustics::RunHooks& hooks) {
  if (hooks.resume) {
    load_solver(s, *hooks.resume);
    acoustics::load_observations(obs, *hooks.resume);
    hooks.resume->expect_end();
    return;
  }
  const auto& out = c.base.output;
  obs.log = parameters_log(c, s);
  obs.bins = acoustics::PsdBins::log_spaced(out.psd_d_min, out.psd_d_max, out.psd_bins);
  obs.initial = counts(s);
}

// Writes a checkpoint of the state at an output time when the schedule says so (force: interruption, end).
void checkpoint(const acoustics::RunHooks& hooks, acoustics::CheckpointSchedule& when, const SectionalSolver& s,
                const AcousticObservations& obs, bool force) {
  if (!when.due(s.time(), force)) return;
  io::CheckpointWriter w;
  save_solver(s, w);
  acoustics::save_observations(obs, w);
  hooks.checkpoint(s.stats().accepted, s.time(), w.bytes());
  when.written(s.time());
}
}  // namespace

AcousticObservations run_sectional(const SectionalCase& c, const acoustics::RunHooks& hooks) {
  const auto wall0 = std::chrono::steady_clock::now();
  const auto& base = c.base;
  SectionalSolver s(c);
  AcousticObservations obs;
  start(c, s, obs, hooks);
  const double te = base.engine.t_end, resumed_at = hooks.resume ? s.time() : -1.0;
  acoustics::CheckpointSchedule when(hooks.checkpoint ? hooks.checkpoint_interval : 0.0, s.time(), hooks.resume);
  for (double t : output_times(base)) {
    if (t <= resumed_at) continue;  // observed before the checkpoint
    s.advance_to(t);
    const acoustics::Counts now = counts(s);
    if (efficiency_due(t, base)) obs.efficiency.push_back(efficiency_row(t, now, obs.initial));
    if (listed(base.output.psd_times, t, te)) obs.psd.push_back({t, psd(s, obs.bins)});
    checkpoint(hooks, when, s, obs, false);
    if (hooks.progress) hooks.progress(t / te, t);
    if (hooks.cancelled && hooks.cancelled()) {
      checkpoint(hooks, when, s, obs, true);
      throw InterruptedError(fmt::format("interrupted at t = {:.6g} s", t));
    }
  }
  checkpoint(hooks, when, s, obs, true);
  obs.final = counts(s);
  obs.last_time_with_pure_droplets = obs.initial.n_phase[1] > 0 ? (obs.final.n_phase[1] > 0 ? te : 0.0) : -1.0;
  obs.samples = s.grid().size();
  obs.steps = s.stats().accepted;
  obs.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  obs.log += closing_log(obs, s);
  return obs;
}

}  // namespace agglo::sectional
