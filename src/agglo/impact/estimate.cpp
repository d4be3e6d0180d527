#include "agglo/impact/estimate.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/electrostatics/estimate.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/structure_target.hpp"

namespace agglo::impact {

namespace {

// Neighbour-list pairs per particle: at most 12 equal spheres touch one, plus the skin's margin.
constexpr double kNeighboursPerParticle = 16.0;
// Text bytes: one timeseries.csv row (six %.9e numbers, a count), one particle of a .vtp snapshot
// (radius, velocity, angular velocity, charge, contacts, position, connectivity, offset) and the
// fixed part of a snapshot file and its particles.pvd line; one run's record in vcrit.json /
// breakup.json plus its journal.jsonl line; result.json, run.json, config.resolved.toml, plots.
constexpr double kRowBytes = 120.0;
constexpr double kSnapshotParticleBytes = 320.0;
constexpr double kSnapshotFixedBytes = 1600.0;
constexpr double kRunRecordBytes = 2048.0;
constexpr double kSmallFilesBytes = 256.0 * 1024.0;
// Outcome record of a run kept in memory by an ensemble (components, fragments, JSON).
constexpr double kOutcomeBytes = 4096.0;

struct Term {
  double value;
  std::vector<std::string> keys;
};

// Particles of a run: the agglomerate's (built-in shapes 4, a list or structure its entries or
// primaries) and the projectile's (1, or an aggregate projectile's primaries).
double particles(const ImpactCase& c) {
  const auto& a = c.agglomerate;
  const std::size_t target = a.shape == "list" ? a.particles.size() : is_structure_shape(a.shape) ? a.structure.size() : 4;
  const std::size_t projectile = c.projectile.shape == "sphere" ? 1 : c.projectile.body.structure.size();
  return static_cast<double>(target + projectile);
}

double approach_bound(const ImpactCase& c, double speed) {
  const double rp = c.agglomerate.radius;
  return c.time.max_approach > 0.0 ? c.time.max_approach
                                   : 5.0 * (c.projectile.gap_radii * rp + rp) / std::max(speed, 1e-3) + 1e-4;
}

std::vector<std::string> dt_keys(const ImpactCase& c) {
  const auto& k = impact_keys();
  if (c.dem.dt > 0.0) return {std::string(k.time.dt.dotted())};
  return {std::string(k.time.steps_per_period.dotted()), std::string(k.material.density.dotted()),
          std::string(k.agglomerate.radius.dotted()), std::string(k.material.surface_energy.dotted())};
}

// Time terms of one run [s] with their keys; `speed_key` names what sets the approach speed.
std::vector<Term> run_time_terms(const ImpactCase& c, double speed, const std::string& speed_key) {
  const auto& k = impact_keys().time;
  std::vector<Term> t;
  if (c.time.max_approach > 0.0)
    t.push_back({approach_bound(c, speed), {std::string(k.max_approach.dotted())}});
  else
    t.push_back({approach_bound(c, speed), {speed_key, std::string(impact_keys().projectile.gap_radii.dotted())}});
  t.push_back({c.time.after_contact, {std::string(k.after_contact.dotted())}});
  t.push_back({c.time.max_extensions * c.time.extension,
               {std::string(k.extension.dotted()), std::string(k.max_extensions.dotted())}});
  return t;
}

// True when the run solves for induced charges (a solver that induces them and a permittivity that
// differs from the medium's); with kappa = kappa_0 every solver reduces to point charges.
bool induced_charges(const ImpactCase& c) {
  if (!c.electrostatics || !es::induces_charges(c.coupling.es.options)) return false;
  bool differs = c.projectile.permittivity != c.medium_permittivity;
  if (c.agglomerate.shape == "list")
    for (const auto& p : c.agglomerate.particles) differs = differs || p.permittivity != c.medium_permittivity;
  else
    differs = differs || c.agglomerate.permittivity != c.medium_permittivity;
  return differs;
}

// Keys of the largest term first, then those of the time step, then the others. A DEM step with
// induced charges counts kInducedChargeStepWeight particle-steps (docs/limits.md).
void add_steps(EstimateItem& item, double value, std::vector<Term> terms, const ImpactCase& c) {
  std::sort(terms.begin(), terms.end(), [](const Term& a, const Term& b) { return a.value > b.value; });
  const bool induced = induced_charges(c);
  item.value += induced ? value * kInducedChargeStepWeight : value;
  add_to(item, 0.0, terms.front().keys);
  add_to(item, 0.0, dt_keys(c));
  if (induced) {
    const auto& es = es::es_keys();
    const std::string_view kappa = c.agglomerate.shape == "list"
                                       ? settings::electrostatics_settings().particles.permittivity.dotted()
                                       : impact_keys().agglomerate.permittivity.dotted();
    add_to(item, 0.0, {std::string(es.solver.dotted()), std::string(kappa)});
  }
}

double relax_steps(const ImpactCase& c) {
  return c.electrostatics && c.time.relax_time > 0.0 ? (c.time.relax_time / time_step(c) + 1.0) * (particles(c) - 1.0)
                                                     : 0.0;
}

// Particle-steps of the relaxation of an aggregate projectile, made by every run (relax_projectile).
double projectile_relax_steps(const ImpactCase& c) {
  if (c.projectile.shape == "sphere" || !c.electrostatics || c.time.relax_time <= 0.0) return 0.0;
  return (c.time.relax_time / time_step(c) + 1.0) * static_cast<double>(c.projectile.body.structure.size());
}

// Memory of one run without recording: particles, neighbour list, electrostatic solver.
double run_memory(const ImpactCase& c) {
  const double n = particles(c);
  const double per_pair = sizeof(dem::Pair) + sizeof(dem::PairForce) + 2.0 * sizeof(std::int64_t);
  double bytes = n * (5.0 * sizeof(Vec3) + 5.0 * sizeof(double)) +
                 n * kNeighboursPerParticle * per_pair;
  if (c.electrostatics) {
    dem::Particles p = build_agglomerate(c);
    add_projectile(p, c, c.projectile.speed);
    es::Problem prob;
    prob.medium_permittivity = c.medium_permittivity;
    for (std::size_t i = 0; i < p.size(); ++i)
      prob.spheres.push_back({p.x[i], es::electrostatic_radius(p.r[i], c.coupling.es.min_gap), p.q[i], p.kappa[i]});
    bytes += es::solver_memory_bytes(c.coupling.es.options, prob);
  }
  return bytes;
}

// An ensemble of runs at `speeds` (each with its approach bound), `threads` at a time.
Estimate ensemble_estimate(const ImpactCase& c, const std::vector<double>& speeds, double runs, int threads,
                           const std::string& speed_key, const std::vector<std::string>& run_keys) {
  Estimate e;
  double steps = relax_steps(c) + runs * projectile_relax_steps(c);
  for (double v : speeds) steps += run_steps_bound(c, v) * particles(c) * (runs / static_cast<double>(speeds.size()));
  add_to(e.steps, 0.0, run_keys);
  add_steps(e.steps, steps, run_time_terms(c, speeds.front(), speed_key), c);
  add_to(e.memory, std::max(1, threads) * run_memory(c) + runs * kOutcomeBytes, run_keys);
  add_to(e.output, runs * kRunRecordBytes + kSmallFilesBytes, run_keys);
  return e;
}

}  // namespace

double time_step(const ImpactCase& c) {
  if (c.dem.dt > 0.0) return c.dem.dt;
  dem::Particles p = build_agglomerate(c);
  if (!c.wall_impact) add_projectile(p, c, c.projectile.speed);  // a smaller projectile has a shorter period
  return dem::reference_period(p, c.dem) / c.dem.steps_per_period;
}

double run_steps_bound(const ImpactCase& c, double speed) {
  const double t = approach_bound(c, speed) + c.time.after_contact + c.time.max_extensions * c.time.extension;
  return t / time_step(c) + c.time.max_extensions + 2.0;
}

double vcrit_runs_bound(const VcritSpec& v) {
  const double spacing = (v.v_max - v.v_min) / (v.scan_points - 1);
  const int per_round = std::max(v.points_per_round, 1);
  const double rounds = std::ceil(std::log(std::max(1.0, spacing / v.tolerance)) / std::log(per_round + 1.0));
  return v.scan_points + rounds * per_round;
}

Estimate collide_estimate(const ImpactCase& c) {
  const auto& k = impact_keys();
  const std::string speed_key(k.projectile.speed.dotted());
  const double n = particles(c), steps = run_steps_bound(c, c.projectile.speed);
  Estimate e;
  add_steps(e.steps, steps * n + relax_steps(c) + projectile_relax_steps(c), run_time_terms(c, c.projectile.speed, speed_key), c);
  // At most one row and one snapshot per step, and one per output interval of the run time.
  const double t_run = approach_bound(c, c.projectile.speed) + c.time.after_contact +
                       c.time.max_extensions * c.time.extension + (c.time.max_extensions + 2.0) * time_step(c);
  const double rows = std::min(steps, t_run / c.output.timeseries_interval) + 2.0;
  const double snaps = c.output.snapshot_interval > 0.0 ? std::min(steps, t_run / c.output.snapshot_interval) + 2.0 : 0.0;
  const std::vector<std::string> out_keys{std::string(k.output.timeseries_interval.dotted()),
                                          std::string(k.output.snapshot_interval.dotted()),
                                          std::string(k.time.after_contact.dotted())};
  const double row_text = rows * kRowBytes;
  const double snap_text = snaps * (kSnapshotFixedBytes + n * kSnapshotParticleBytes);
  add_to(e.output, row_text + snap_text + kSmallFilesBytes, out_keys);
  // Recorded rows and snapshots (vector capacity up to 2x), the CSV text while it is written.
  const double recorded = 2.0 * rows * sizeof(TimeseriesRow) +
                          snaps * (2.0 * sizeof(std::pair<double, dem::ParticleSnapshot>) + n * 96.0);
  add_to(e.memory, run_memory(c) + recorded + row_text, out_keys);
  return e;
}

Estimate vcrit_estimate(const ImpactCase& c, int threads) {
  const auto& k = impact_keys().vcrit;
  const double runs = vcrit_runs_bound(c.vcrit);
  return ensemble_estimate(c, {c.vcrit.v_min}, runs, threads, std::string(k.v_min.dotted()),
                           {std::string(k.scan_points.dotted()), std::string(k.tolerance.dotted()),
                            std::string(k.points_per_round.dotted())});
}

Estimate breakup_estimate(const ImpactCase& c, int threads) {
  const auto& k = impact_keys().breakup;
  std::vector<double> speeds = c.breakup.speeds;
  std::sort(speeds.begin(), speeds.end());
  const double runs = static_cast<double>(speeds.size()) * c.breakup.samples * c.breakup.orientations;
  return ensemble_estimate(c, speeds, runs, threads, std::string(k.speeds.dotted()),
                           {std::string(k.speeds.dotted()), std::string(k.samples.dotted()),
                            std::string(k.orientations.dotted())});
}

}  // namespace agglo::impact
