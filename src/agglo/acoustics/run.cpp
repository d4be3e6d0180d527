#include "agglo/acoustics/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "agglo/acoustics/checkpoint.hpp"
#include "agglo/acoustics/engine.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/settings_acoustic.hpp"

namespace agglo::acoustics {

namespace {

std::string binned_report(const CollisionStats& s) {
  const double acc = s.trials ? 100.0 * static_cast<double>(s.collisions) / static_cast<double>(s.trials) : 0.0;
  return fmt::format(
      "binned: particle_steps={} candidates={} kernel_evals={} collisions={} ({:.3g}% of candidates) "
      "coalescences(droplet,dry,wet)=({},{},{}) rebounds(droplet,dry,wet)=({},{},{})\n"
      "binned majorants: full_row_rate_computations={} max beta/majorant={:.4g} violations(beta>majorant)={} "
      "cell_steps_subdivided={} max_substeps={}\n"
      "binned refills={} dead_samples={} split_merge_energy_lost={:.6g} J compensated={:.6g} J\n",
      s.particle_steps, s.trials, s.kernel_evals, s.collisions, acc, s.coalescences[0], s.coalescences[1],
      s.coalescences[2], s.rebounds[0], s.rebounds[1], s.rebounds[2], s.row_rate_updates, s.max_pn, s.violations, s.subcycled,
      s.max_subcycles, s.refills,
      s.dead, s.energy_lost, s.energy_returned);
}

std::string guard_report(const CollisionStats& s, Selection sel) {
  if (sel == Selection::binned) return binned_report(s);
  return fmt::format(
      "nanbu: particle_steps={} trials={} kernel_evals={} collisions={} coalescences(droplet,dry,wet)=({},{},{}) "
      "rebounds(droplet,dry,wet)=({},{},{})\n"
      "nanbu guard: max N*P_bound(dt_c)={:.4g} subcycled_particle_steps={} ({:.3g}%) max_subcycles={} "
      "max N*P_ij evaluated={:.4g} violations(P_ij>1/N)={}\n"
      "nanbu refills={} dead_samples={} split_merge_energy_lost={:.6g} J compensated={:.6g} J\n",
      s.particle_steps, s.trials, s.kernel_evals, s.collisions, s.coalescences[0], s.coalescences[1], s.coalescences[2],
      s.rebounds[0], s.rebounds[1], s.rebounds[2], s.max_bound_pn, s.subcycled,
      s.particle_steps ? 100.0 * static_cast<double>(s.subcycled) / static_cast<double>(s.particle_steps) : 0.0,
      s.max_subcycles, s.max_pn, s.violations, s.refills, s.dead, s.energy_lost, s.energy_returned);
}

bool due(double t, double target, double dt) { return std::abs(t - target) < 0.5 * dt; }

const char* integrator_name(Integrator i) {
  return i == Integrator::exact ? "exact" : i == Integrator::none ? "none" : "explicit";
}

// Derived parameters of the gas, sound, domain and time stepping (first lines of run.log).
std::string parameters_log(const AcousticCase& c, const Engine& eng) {
  const auto& S = eng.settings();
  const Motion& M = S.motion;
  std::string log = fmt::format("agglo acoustic: case {}\n", c.file);
  log += fmt::format("gas: T={:g} K P={:g} Pa rho_g={:.6g} kg/m^3 c={:.6g} m/s mu_g={:.6g} Pa s lambda_g={:.6g} m "
                     "gravity={:g} m/s^2\n",
                     M.gas.temperature, M.gas.pressure, M.gas.density, M.gas.sound_speed, M.gas.viscosity,
                     M.gas.mean_free_path, M.gas.gravity);
  log += fmt::format("sound: enabled={} L={:g} dB f={:g} Hz u_amp={:.6g} m/s wavelength={:.6g} m\n", M.sound.enabled,
                     M.sound.level_db, M.sound.frequency, M.sound.u_amp, M.sound.wavelength);
  log += fmt::format("domain: {:.6g} x {:.6g} x {:.6g} m, cells {}x{}x{}, V_c={:.6g} m^3\n", M.domain.L[0],
                     M.domain.L[1], M.domain.L[2], M.domain.cells[0], M.domain.cells[1], M.domain.cells[2],
                     M.domain.cell_volume());
  log += fmt::format("time: end={:g} s collision_dt={:g} s motion_dt={:g} s ({} motion sub-steps) integrator={} "
                     "kernel={}\n",
                     S.t_end, S.collision_dt, S.motion_dt, eng.motion_substeps(), integrator_name(M.integrator),
                     S.kernel.model);
  return log;
}

// C_I is held piecewise constant over a motion step. With an odd or fractional-but-locked number of
// steps per acoustic period the sampled phases are not symmetric under psi -> psi + pi and a droplet
// with C_I > 1 picks up a spurious mean drift (docs/acoustics.md sec. 3). Returns "" when fine.
std::string step_warning(const EngineSettings& S) {
  const Motion& M = S.motion;
  if (M.integrator != Integrator::exact || M.sound.u_amp <= 0.0 || !M.inertia_correction) return {};
  const double per = 1.0 / (M.sound.frequency * S.motion_dt);
  const double even = 2.0 * std::round(0.5 * per);
  if (per >= 40.0 || std::abs(per - even) <= 1e-6 * per) return {};
  return fmt::format(
      "motion_dt = {:g} s gives {:.4g} steps per acoustic period; use an even whole number "
      "(e.g. motion_dt = {:g} s) to avoid a spurious drift of droplets with C_I > 1",
      S.motion_dt, per, 1.0 / (M.sound.frequency * std::max(2.0, even)));
}

// Samples per cell and clone factor of population k ([sampling], initial_placement.hpp).
std::string placement_log(std::size_t k, const SampledPopulation& sp, const EngineSettings& S) {
  const auto cells = static_cast<std::size_t>(S.motion.domain.num_cells());
  const bool strat = S.sampling.placement == Placement::stratified;
  return fmt::format("population {} sampling: placement={} samples per cell={:.6g} ({}) clone factor={} ({} samples "
                     "requested, min_samples_per_cell={})\n",
                     k, strat ? "stratified" : "random", static_cast<double>(sp.count) / static_cast<double>(cells),
                     strat ? fmt::format("each cell {} or {}", sp.count / cells, (sp.count + cells - 1) / cells)
                           : std::string("on average"),
                     sp.clone_factor, sp.requested, S.sampling.min_samples_per_cell);
}

// Sampling of each population; warns when integer weights miss the requested number by > 1 %.
std::string sampling_log(const Engine& eng, const RunHooks& hooks) {
  const auto& S = eng.settings();
  std::string log;
  for (std::size_t k = 0; k < eng.sampled().size(); ++k) {
    const auto& sp = eng.sampled()[k];
    const double rel = sp.real_number > 0 ? sp.weight_sum / sp.real_number - 1.0 : 0.0;
    log += fmt::format("population {} '{}': {} samples, requested N V = {:.6g}, sum of integer weights = {:.6g} "
                       "(rel. diff {:.3g})\n",
                       k, S.populations[k].name, sp.count, sp.real_number, sp.weight_sum, rel);
    log += placement_log(k, sp, S);
    if (sp.real_number > 0 && std::abs(rel) > 0.01) {
      const std::string w = fmt::format(
          "population {} '{}': the integer sample weights represent {:.4g} particles instead of {:.4g} "
          "({:+.2f} %); set weight_rounding = \"conserving\" or choose samples so that N V / samples is near a "
          "whole number",
          k, S.populations[k].name, sp.weight_sum, sp.real_number, 100.0 * rel);
      log += "warning: " + w + "\n";
      if (hooks.warning) hooks.warning(w);
    }
  }
  return log;
}

// The startup line of a table outcome model (`kind` "dry" or "wet"): file, axes, provenance.
std::string table_model_log(const char* kind, const OutcomeTable& t) {
  return fmt::format("{} outcome model: table {} ({} speeds {:.4g}-{:.4g} m/s x {} x {} diameters {:.4g}-{:.4g} m; "
                     "provenance: {})\n",
                     kind, t.source, t.axes[0].size(), t.axes[0].front(), t.axes[0].back(), t.axes[1].size(),
                     t.axes[2].size(), std::min(t.axes[1].front(), t.axes[2].front()),
                     std::max(t.axes[1].back(), t.axes[2].back()), t.provenance.empty() ? "none" : t.provenance);
}

// The closing lines of a table outcome model: its queries and clamps, its pairs turned back.
std::string table_counts_log(const char* kind, std::uint64_t queries, std::uint64_t clamped) {
  return fmt::format("{} outcome table: queries={} clamped={} ({:.3g}% outside the table, clamped to its ends)\n",
                     kind, queries, clamped,
                     queries ? 100.0 * static_cast<double>(clamped) / static_cast<double>(queries) : 0.0);
}
std::string turned_back_log(const char* kind, std::uint64_t turned_back) {
  return fmt::format("{} outcome table: Coulomb work before the launch gap: {} pairs turned back (bounced "
                     "elastically without contact; docs/acoustics.md §1.7)\n",
                     kind, turned_back);
}

std::string startup_log(const AcousticCase& c, const Engine& eng, const RunHooks& hooks) {
  std::string log = parameters_log(c, eng);
  if (const std::string w = step_warning(eng.settings()); !w.empty()) {
    log += "warning: " + w + "\n";
    if (hooks.warning) hooks.warning(w);
  }
  log += sampling_log(eng, hooks);
  if (const auto& t = eng.settings().outcomes.dry_table; t && eng.settings().outcomes.dry_model == OutcomeModel::table)
    log += table_model_log("dry", *t);
  if (const auto& t = eng.settings().outcomes.wet_table; t && eng.settings().outcomes.wet_model == OutcomeModel::table)
    log += table_model_log("wet", *t);
  if (eng.settings().selection == Selection::binned)
    log += fmt::format("selection: binned ({} size classes per octave of diameter, weight classes by powers of {}, "
                       "one majorant per group pair and kernel mechanism)\n",
                       kSizeClassesPerOctave, 1 << kWeightOctavesPerClass);
  else
    log += fmt::format("nanbu guard at start: max N*P_bound(dt_c) = {:.4g} ({})\n", eng.max_guard_pn(),
                       eng.max_guard_pn() > 1.0 ? "sub-cycling needed" : "bound met without sub-cycling");
  return log;
}

double rel_change(double a, double b) { return a > 0 ? b / a - 1 : 0.0; }

// Collisions that stuck, bounced and broke by pair type over the run (outcomes_by_pair.csv).
std::string outcomes_log(const CollisionStats& s) {
  std::string log = "outcomes by pair type (collisions: stuck / bounced / broke, fraction of the type's collisions)";
  const auto frac = [](std::uint64_t n, std::uint64_t of) {
    return of ? static_cast<double>(n) / static_cast<double>(of) : 0.0;
  };
  for (std::size_t k = 0; k < 3; ++k) {
    const std::uint64_t n = s.coalescences[k] + s.rebounds[k] + s.breakups[k];
    log += fmt::format("{} {}: {}: {} ({:.4g}) / {} ({:.4g}) / {} ({:.4g})", k ? ";" : ":", kPairTypeNames[k], n,
                       s.coalescences[k], frac(s.coalescences[k], n), s.rebounds[k], frac(s.rebounds[k], n),
                       s.breakups[k], frac(s.breakups[k], n));
  }
  return log + "\n";
}

// PM mass at t = 0 and at the last row, and the reductions (efficiency.csv's pm columns).
std::string pm_log(const AcousticObservations& o) {
  const PmMass &a = o.efficiency.front().pm, &b = o.efficiency.back().pm;
  std::string log = fmt::format("PM mass [ug/m^3] t = 0 -> {:.6g} s (reduction 1 - PM(t)/PM(0)), diameter d < cut:",
                                o.efficiency.back().t);
  for (const bool aero : {false, true}) {
    log += aero ? "; aerodynamic" : " volume-equivalent";
    const auto& m0 = aero ? a.aerodynamic : a.volume;
    const auto& m1 = aero ? b.aerodynamic : b.volume;
    for (std::size_t k = 0; k < 3; ++k)
      log += fmt::format(" {} {:.6g} -> {:.6g} ({:.4g})", kPmLabels[k], m0[k] * kMicrogramsPerKg,
                         m1[k] * kMicrogramsPerKg, pm_reduction(m0[k], m1[k]));
  }
  return log + "\n";
}

// The warning of a run whose largest collision diameter exceeded kCellDiameterFraction of the smallest cell
// edge at some efficiency row ("" otherwise): when first and how often, and the largest ratio.
std::string cell_size_warning(const AcousticObservations& o) {
  if (!(o.min_cell_edge > 0.0)) return "";
  std::size_t over = 0;
  double t_first = -1.0, worst = 0.0, t_worst = 0.0;
  for (const EfficiencyRow& r : o.efficiency) {
    const double ratio = r.largest_collision_diameter / o.min_cell_edge;
    if (ratio > kCellDiameterFraction && over++ == 0) t_first = r.t;
    if (ratio > worst) worst = ratio, t_worst = r.t;
  }
  if (over == 0) return "";
  return fmt::format("cell size: the largest collision diameter exceeded {:g} of the smallest cell edge {:.4g} m in {} "
                     "of {} efficiency rows (first at t = {:.6g} s), up to {:.4g} m ({:.3g} of the edge) at t = "
                     "{:.6g} s; the cells assume particles much smaller than the cell: use fewer cells "
                     "(docs/acoustics.md §1.8)",
                     kCellDiameterFraction, o.min_cell_edge, over, o.efficiency.size(), t_first,
                     worst * o.min_cell_edge, worst, t_worst);
}

std::string closing_log(const AcousticObservations& o) {
  const Counts &c0 = o.initial, &c1 = o.final;
  const EfficiencyRow& last = o.efficiency.back();
  std::string log = guard_report(o.stats, o.selection) + outcomes_log(o.stats) + pm_log(o);
  if (const std::string w = cell_size_warning(o); !w.empty()) log += "warning: " + w + "\n";
  if (o.dry_table)
    log += table_counts_log("dry", o.stats.table_queries, o.stats.table_clamped);
  if (o.coulomb_launch) log += turned_back_log("dry", o.stats.table_turned_back);
  if (o.wet_table) log += table_counts_log("wet", o.stats.wet_table_queries, o.stats.wet_table_clamped);
  if (o.wet_coulomb_launch) log += turned_back_log("wet", o.stats.wet_table_turned_back);
  if (!o.interrupted.empty()) log += "incomplete: " + o.interrupted + "\n";
  log += fmt::format("conservation: solid volume fraction {:.17g} -> {:.17g} (rel. {:.3g}); liquid {:.17g} -> {:.17g} "
                     "(rel. {:.3g}); mass {:.17g} -> {:.17g}\n",
                     c0.solid_volume, c1.solid_volume, rel_change(c0.solid_volume, c1.solid_volume), c0.liquid_volume,
                     c1.liquid_volume, rel_change(c0.liquid_volume, c1.liquid_volume), c0.mass, c1.mass);
  log += fmt::format("result: fine_efficiency={:.6g} pure_droplet_fraction={:.6g} wall_time={:.3f} s\n",
                     last.fine_efficiency, last.pure_droplet_fraction, o.wall_time_s);
  return log;
}

// Records the observations of the state at step s (efficiency every efficiency_interval, PSDs and
// snapshots at their times).
class Observer {
 public:
  Observer(const AcousticCase& c, const Engine& eng, AcousticObservations& obs)
      : c_(c), eng_(eng), obs_(obs), V_(eng.settings().motion.domain.volume()) {
    const double dt = eng.settings().collision_dt;
    every_ = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(c.output.efficiency_interval / dt)));
  }

  // The initial state: its counts, the PSD bins and the observations of step 0 (not on a resumed run,
  // whose observations so far come from the checkpoint).
  void start() {
    obs_.initial = count(eng_.particles(), V_);
    obs_.bins = PsdBins::log_spaced(c_.output.psd_d_min, c_.output.psd_d_max, c_.output.psd_bins);
    obs_.last_time_with_pure_droplets = obs_.initial.n_phase[1] > 0 ? 0.0 : -1.0;
    observe(0);
  }

  void observe(std::uint64_t s) {
    const double dt = eng_.settings().collision_dt, t = static_cast<double>(s) * dt;
    if (s % every_ == 0 || s == eng_.total_steps()) efficiency(t);
    for (double tp : c_.output.psd_times)
      if (due(t, tp, dt)) obs_.psd.push_back({t, psd(eng_.particles(), V_, obs_.bins)});
    for (double ts : c_.output.snapshot_times)
      if (due(t, ts, dt)) snapshot(t);
  }

 private:
  void efficiency(double t) {
    EfficiencyRow r;
    r.t = t;
    r.counts = count(eng_.particles(), V_);
    const double nf0 = obs_.initial.n_phase[0], nl0 = obs_.initial.n_phase[1];
    r.fine_efficiency = nf0 > 0 ? (nf0 - r.counts.n_phase[0]) / nf0 : 0.0;
    r.pure_droplet_fraction = nl0 > 0 ? r.counts.n_phase[1] / nl0 : 0.0;
    if (r.counts.n_phase[1] > 0) obs_.last_time_with_pure_droplets = t;
    r.collisions = eng_.stats().collisions;
    r.subcycled = eng_.stats().subcycled;
    r.pm = pm_mass(eng_.particles(), V_, eng_.settings().motion.gas);
    const SampleSet& p = eng_.particles();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.w[i] > 0.0) r.largest_collision_diameter = std::max(r.largest_collision_diameter, p.d[i]);
    obs_.efficiency.push_back(r);
  }

  void snapshot(double t) {
    const SampleSet& p = eng_.particles();
    const double xmax = c_.output.snapshot_x_fraction * eng_.settings().motion.domain.L[0];
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.w[i] > 0 && p.x[i] <= xmax)
        obs_.snapshots.push_back({t, p.x[i], p.y[i], p.z[i], p.volume_diameter(i), p.vol_s[i], p.vol_l[i], p.w[i], p.id[i], p.phase(i)});
  }

  const AcousticCase& c_;
  const Engine& eng_;
  AcousticObservations& obs_;
  double V_;
  std::uint64_t every_ = 1;
};

}  // namespace

namespace {
// The start-up state needs more Nanbu sub-cycles than time.max_subcycles: names the collision step (the
// key to change) and the population of the sample that needs the most, with the inputs that drive it.
std::string subcycle_message(const AcousticCase& c, const Engine& e, std::size_t worst, double pn) {
  const auto& K = settings::acoustic_settings().time;
  const auto& s = e.settings();
  const SampleSet& p = e.particles();
  const int pop = p.pop[worst];
  const auto& spec = s.populations[static_cast<std::size_t>(pop)];
  return fmt::format("{}: key '{}' = {:g}: the Nanbu bound P_ij <= 1/N needs {:.4g} sub-cycles per collision step "
                     "at the start (limit {} = {}), for a sample of population {} '{}' (d = {:.4g} m, rho = {:.4g} "
                     "kg/m^3, number concentration {:.4g} 1/m^3, weight {:.4g}); reduce {} or that population's "
                     "concentration or size",
                     c.file, K.collision_dt.dotted(), s.collision_dt, std::ceil(pn), K.max_subcycles.dotted(),
                     s.max_subcycles, pop, spec.name, p.d[worst], p.rho[worst], spec.number_concentration,
                     p.w[worst], K.collision_dt.dotted());
}
}  // namespace

void check_startup(const AcousticCase& c, const Engine& e) {
  const auto& K = settings::acoustic_settings().time;
  const auto& s = c.engine;
  const SampleSet& p = e.particles();
  if (s.motion.integrator == Integrator::explicit_euler) {
    double tmin = std::numeric_limits<double>::infinity();
    std::size_t imin = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.tau[i] < tmin) {
        tmin = p.tau[i];
        imin = i;
      }
    if (s.motion_dt >= 2.0 * tmin)
      throw ConfigError(fmt::format("{}: key '{}' = {:g}: the explicit integrator is unstable for "
                                    "motion_dt >= 2 tau; particle {} (d = {:.4g} m) has tau = {:.4g} s "
                                    "(use integrator = \"exact\" or a smaller step)",
                                    c.file, K.motion_dt.dotted(), s.motion_dt, p.id[imin], p.d[imin], tmin));
  }
  if (s.selection != Selection::nanbu) return;  // the Nanbu bound concerns the Nanbu selection only
  std::size_t worst = 0;
  const double pn = e.max_guard_pn(&worst);
  if (s.strict_guard && pn > 1.0)
    throw ConfigError(fmt::format("{}: key '{}' = {:g}: the Nanbu bound P_ij <= 1/N cannot be met "
                                  "(initial N P_bound = {:.4g}) and {} = \"strict\"; reduce collision_dt "
                                  "by {:.3g}x or use nanbu_guard = \"subcycle\"",
                                  c.file, K.collision_dt.dotted(), s.collision_dt, pn, K.nanbu_guard.dotted(), pn));
  if (std::ceil(pn) > static_cast<double>(s.max_subcycles))
    throw ConfigError(subcycle_message(c, e, worst, pn));
}

namespace {
// Writes the checkpoints of a run (RunHooks::checkpoint) when its CheckpointSchedule says so.
class Checkpointer {
 public:
  Checkpointer(const RunHooks& h, const Engine& e, const AcousticObservations& o)
      : h_(h), e_(e), o_(o), when_(h.checkpoint ? h.checkpoint_interval : 0.0, e.time(), h.resume != nullptr) {}
  // After a step; force: the run stops here (interruption or end).
  void at_step(bool force) {
    if (!when_.due(e_.time(), force)) return;
    io::CheckpointWriter w;
    save_engine(e_, w);
    save_observations(o_, w);
    h_.checkpoint(e_.step_index(), e_.time(), w.bytes());
    when_.written(e_.time());
  }

 private:
  const RunHooks& h_;
  const Engine& e_;
  const AcousticObservations& o_;
  CheckpointSchedule when_;
};
}  // namespace

AcousticObservations run_acoustic(const AcousticCase& c, const RunHooks& hooks) {
  const auto wall0 = std::chrono::steady_clock::now();
  Engine eng(c.engine);
  AcousticObservations obs;
  Observer observer(c, eng, obs);
  if (hooks.resume) {  // continue from a checkpoint: the engine's state and the observations so far
    load_engine(eng, *hooks.resume);
    load_observations(obs, *hooks.resume);
    hooks.resume->expect_end();
  } else {
    check_startup(c, eng);
    obs.log = startup_log(c, eng, hooks);
    observer.start();
  }
  Checkpointer checkpoints(hooks, eng, obs);
  const std::uint64_t nsteps = eng.total_steps();
  for (std::uint64_t s = eng.step_index() + 1; s <= nsteps; ++s) {
    eng.step();
    observer.observe(s);
    checkpoints.at_step(false);
    if ((s & 63) != 0) continue;
    if (hooks.progress) hooks.progress(static_cast<double>(s) / static_cast<double>(nsteps), eng.time());
    if (hooks.cancelled && hooks.cancelled()) {
      obs.interrupted = fmt::format("interrupted at t = {:.6g} s (step {} of {})", eng.time(), s, nsteps);
      obs.steps = s;
      break;
    }
  }
  if (hooks.checkpoint_at_end || !obs.interrupted.empty()) checkpoints.at_step(true);  // where the run stops
  obs.final = count(eng.particles(), eng.settings().motion.domain.volume());
  obs.samples = eng.particles().size();
  if (obs.interrupted.empty()) obs.steps = nsteps;
  obs.u_amp = eng.settings().motion.sound.u_amp;
  obs.stats = eng.stats();
  obs.selection = eng.settings().selection;
  const OutcomeParams& oc = eng.settings().outcomes;
  obs.dry_table = oc.dry_model == OutcomeModel::table;
  obs.coulomb_launch = obs.dry_table && eng.particles().carries_charge && oc.dry_table->has_launch_gap();
  obs.wet_table = oc.wet_model == OutcomeModel::table;
  obs.wet_coulomb_launch = obs.wet_table && eng.particles().carries_charge && oc.wet_table->has_launch_gap();
  obs.dsmc = true;
  const auto& dom = eng.settings().motion.domain;
  obs.min_cell_edge = std::min({dom.L[0] / dom.cells[0], dom.L[1] / dom.cells[1], dom.L[2] / dom.cells[2]});
  if (const std::string w = cell_size_warning(obs); !w.empty() && hooks.warning) hooks.warning(w);
  obs.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  obs.log += closing_log(obs);
  return obs;
}

}  // namespace agglo::acoustics
