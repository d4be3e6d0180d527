#include "agglo/acoustics/case_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "agglo/acoustics/kernels/keys.hpp"
#include "agglo/acoustics/kernels/registry.hpp"
#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/io/netcdf_reader.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/settings_acoustic.hpp"

namespace agglo::acoustics {

namespace {

const settings::AcousticSettings& keys() { return settings::acoustic_settings(); }

bool near_integer(double x, double tol = 1e-6) { return std::abs(x - std::round(x)) <= tol * std::max(1.0, std::abs(x)); }

void parse_distribution(const ConfigSection& s, const std::string& dist, PopulationSpec& p) {
  const auto& k = keys().population;
  if (dist == "lognormal") {
    p.distribution = Distribution::lognormal;
    p.geometric_mean_diameter = k.geometric_mean_diameter.read(s);
    p.geometric_std = k.geometric_std.read(s);
    p.bins = static_cast<int>(k.bins.read(s));
    p.lognormal_range = k.lognormal_range.read(s);
    p.lognormal_equal_weights = k.lognormal_weights.read(s) == "equal";
    if (p.samples < p.bins)
      k.samples.reject(s, fmt::format("needs at least one sample per bin ({} = {})", k.bins.leaf(), p.bins));
  } else if (dist == "monodisperse") {
    p.distribution = Distribution::monodisperse;
    p.diameter = k.diameter.read(s);
  } else if (dist == "exponential") {
    p.distribution = Distribution::exponential;
    p.mean_volume = k.mean_volume.read(s);
  } else {
    p.distribution = Distribution::table;
    p.table_diameters = k.table_diameters.read(s);
    p.table_fractions = k.table_fractions.read(s);
    if (p.table_diameters.empty()) k.table_diameters.reject(s, "needs at least one diameter");
    if (p.table_fractions.size() != p.table_diameters.size())
      k.table_fractions.reject(s, fmt::format("needs one fraction per entry of {}", k.table_diameters.leaf()));
    double f = 0.0;
    for (double x : p.table_fractions) f += x;
    if (!(f > 0.0)) k.table_fractions.reject(s, "needs a positive sum");
  }
}

// population.structure and its keys, each read only when set (a compact case's resolved config is unchanged).
void parse_structure(const ConfigSection& s, PopulationSpec& p) {
  const auto& k = keys().population;
  const bool fractal = k.structure.present(s) && k.structure.read(s) == settings::kStructureFractal;
  const settings::Setting* fractal_keys[] = {&k.primary_radius, &k.fractal_dimension, &k.fractal_prefactor,
                                             &k.mobility_radius, &k.fractal_law};
  if (!fractal) {
    for (const settings::Setting* key : fractal_keys)
      if (key->present(s))
        key->reject(s, fmt::format("is read only with {} = \"{}\"", k.structure.dotted(), settings::kStructureFractal));
    return;
  }
  if (p.phase != Phase::solid) k.structure.reject(s, "droplets are compact spheres: only a solid population is fractal");
  StructureLaw& law = p.structure;
  law.fractal = true;
  law.primary_radius = k.primary_radius.read(s);
  law.from_table = k.fractal_law.present(s) && k.fractal_law.read(s) == settings::kFractalLawTable;
  if (law.from_table) {  // D_f, k_f from the outcome table: apply_table_fractal_law, after [outcomes]
    for (const settings::Real* key : {&k.fractal_dimension, &k.fractal_prefactor})
      if (key->present(s))
        key->reject(s, fmt::format("is taken from the outcome table with {} = \"{}\": remove it", k.fractal_law.dotted(),
                                   settings::kFractalLawTable));
  } else {
    law.fractal_dimension = k.fractal_dimension.read(s);
    law.fractal_prefactor = k.fractal_prefactor.read(s);
  }
  law.mobility = k.mobility_radius.present(s) && k.mobility_radius.read(s) == settings::kMobilitySorensen
                     ? MobilityRule::sorensen
                     : MobilityRule::collision;
}

PopulationSpec parse_population(const ConfigSection& s) {
  const auto& k = keys().population;
  PopulationSpec p;
  p.name = k.name.read(s);
  p.phase = k.phase.read(s) == "solid" ? Phase::solid : Phase::liquid;
  const std::string dist = k.distribution.read(s);
  p.number_concentration = k.number_concentration.read(s);
  p.density = k.density.read_or(s, p.phase == Phase::solid ? kDefaultSolidDensity : kDefaultLiquidDensity);
  p.samples = k.samples.read(s);
  p.conserving_rounding = k.weight_rounding.read(s) == "conserving";
  parse_distribution(s, dist, p);
  parse_structure(s, p);
  p.charged = k.charge_density.present(s);
  if (p.charged) p.charge_density = k.charge_density.read(s);
  if (k.permittivity.present(s)) p.permittivity = k.permittivity.read(s);
  return p;
}

// [gas] and [sound]; returns whether the sound field is on.
bool parse_gas_sound(const ConfigSection& root, EngineSettings& e) {
  const auto& kg = keys().gas;
  ConfigSection g = kg.t.open(root);
  const double T = kg.temperature.read(g);
  const double P = kg.pressure.read(g);
  const bool gravity = kg.gravity.read(g);
  std::optional<double> mu, lam;
  if (kg.viscosity.present(g)) mu = kg.viscosity.read(g);
  if (kg.mean_free_path.present(g)) lam = kg.mean_free_path.read(g);
  e.motion.gas = Gas::air(T, P, gravity, mu, lam);

  const auto& ks = keys().sound;
  ConfigSection so = ks.t.open(root);
  const bool sound_on = ks.enabled.read(so);
  const double L = ks.level_db.read(so);
  const double f = ks.frequency_hz.read(so);
  e.motion.sound = Sound::make(e.motion.gas, sound_on, L, f);
  if (sound_on) {
    const double ua = Sound::amplitude(e.motion.gas, L);
    const double cmax = 0.1 * e.motion.gas.sound_speed;
    if (!(ua > 0.0) || ua > cmax)
      ks.level_db.reject(so, fmt::format("gives u_amp = {:.4g} m/s; the linear travelling-wave model needs "
                                         "0 < u_amp <= 0.1 c = {:.4g} m/s (L <= {:.1f} dB)",
                                         ua, cmax, 20.0 * std::log10(cmax / Sound::amplitude(e.motion.gas, 0.0))));
  }
  return sound_on;
}

void parse_time(const ConfigSection& root, EngineSettings& e) {
  const auto& k = keys().time;
  ConfigSection ti = k.t.open(root);
  e.t_end = k.end.read(ti);
  e.collision_dt = k.collision_dt.read(ti);
  e.motion_dt = k.motion_dt.read_or(ti, e.collision_dt);
  if (e.motion_dt > e.collision_dt * (1.0 + 1e-12))
    k.motion_dt.reject(ti, fmt::format("must not exceed {} = {:g} s", k.collision_dt.dotted(), e.collision_dt));
  if (!near_integer(e.collision_dt / e.motion_dt, 1e-9))
    k.motion_dt.reject(ti, fmt::format("must divide {} = {:g} s into a whole number of steps", k.collision_dt.dotted(),
                                       e.collision_dt));
  if (!near_integer(e.t_end / e.collision_dt, 1e-6))
    k.end.reject(ti, fmt::format("must be a whole number of collision steps ({:g} s)", e.collision_dt));
  const std::string integ = k.integrator.read(ti);
  e.motion.integrator = integ == "exact"      ? Integrator::exact
                        : integ == "explicit" ? Integrator::explicit_euler
                                              : Integrator::none;
  const std::string iv = k.initial_velocity.read(ti);
  e.initial_velocity = iv == "steady" ? InitialVelocity::steady : iv == "gas" ? InitialVelocity::gas : InitialVelocity::rest;
  // The default by cost (docs/acoustics.md §1.6): without motion the binned groups are kept from step to step
  // and a step costs the collisions (1/26-1/28 of nanbu's CPU on PartMC's Brownian case); with motion they
  // are re-bounded every step (2.9x nanbu's CPU on the acoustic baseline).
  const bool still = e.motion.integrator == Integrator::none;
  e.selection = k.selection.read_or(ti, still ? "binned" : "nanbu") == "binned" ? Selection::binned : Selection::nanbu;
  e.strict_guard = k.nanbu_guard.read(ti) == "strict";
  e.max_subcycles = static_cast<std::uint64_t>(k.max_subcycles.read(ti));
}

// Largest diameter a population can hold at the start [m] (lognormal: d_g sigma_g^range).
double largest_diameter(const PopulationSpec& p) {
  double d = 0.0;
  if (p.distribution == Distribution::monodisperse) d = p.diameter;
  if (p.distribution == Distribution::lognormal) d = p.geometric_mean_diameter * std::pow(p.geometric_std, p.lognormal_range);
  if (p.distribution == Distribution::table)
    for (double x : p.table_diameters) d = std::max(d, x);
  if (p.structure.fractal && d > 0.0) {  // its collision diameter (structure.hpp)
    const double rp = p.structure.primary_radius;
    d = 2.0 * collision_radius(p.structure, std::pow(0.5 * d / rp, 3), rp, 0.5 * d);
  }
  return d;
}

// [[population]]; returns the largest particle diameter [m].
double parse_populations(const ConfigSection& root, EngineSettings& e) {
  const auto& table = keys().population.t;
  auto pops = table.elements(root);
  if (pops.empty()) table.fail(root, fmt::format("at least one [[{}]] table is required", table.name()));
  double dmax = 0.0;
  for (auto& ps : pops) {
    PopulationSpec p = parse_population(ps);
    const bool empty = p.number_concentration == 0.0 ||
                       (p.distribution == Distribution::monodisperse && p.diameter == 0.0);
    if (empty) continue;  // a population with no particles (e.g. the "0 um" / "0 cm^-3" sweep point)
    dmax = std::max(dmax, largest_diameter(p));
    e.populations.push_back(p);
  }
  return dmax;
}

void check_cells(const settings::AcousticSettings::Domain& k, const ConfigSection& dm, const EngineSettings& e,
                 double dmax) {
  const std::int64_t cells = e.motion.domain.num_cells();
  if (cells > kMaxCells)
    k.cells_x.reject(dm, fmt::format("gives {} x {} x {} = {} cells ({}, {}, {}), more than the limit of {} cells",
                                     e.motion.domain.cells[0], e.motion.domain.cells[1], e.motion.domain.cells[2],
                                     cells, k.cells_x.dotted(), k.cells_y.dotted(), k.cells_z.dotted(), kMaxCells));
  const settings::Integer* ck[3] = {&k.cells_x, &k.cells_y, &k.cells_z};
  for (int i = 0; i < 3; ++i) {
    const double edge = e.motion.domain.L[i] / e.motion.domain.cells[i];
    if (edge > dmax) continue;
    std::string who;
    for (const auto& p : e.populations)
      if (largest_diameter(p) == dmax) who = p.name;
    ck[i]->reject(dm, fmt::format("gives cell edge {:.4g} m, not larger than the largest particle (d = {:.4g} m in "
                                  "population '{}'): the cells do not fit; use fewer cells or check that "
                                  "population's diameter", edge, dmax, who));
  }
  std::int64_t total_samples = 0;
  for (const auto& p : e.populations) total_samples += p.samples;
  if (cells > std::max<std::int64_t>(1, total_samples))
    k.cells_x.reject(dm, fmt::format("gives {} cells for {} sampled particles: the cells do not fit (need at "
                                     "least one sample per cell on average)",
                                     e.motion.domain.num_cells(), total_samples));
}

void parse_domain(const ConfigSection& root, bool sound_on, double dmax, EngineSettings& e) {
  const auto& k = keys().domain;
  ConfigSection dm = k.t.open(root);
  const double lam_w = e.motion.sound.wavelength;
  const double Lx = k.length_x.read_or(dm, sound_on ? std::optional<double>(lam_w) : std::nullopt);
  e.motion.domain.L[0] = Lx;
  e.motion.domain.L[1] = k.length_y.read(dm);
  e.motion.domain.L[2] = k.length_z.read(dm);
  e.motion.domain.cells[0] = static_cast<int>(k.cells_x.read(dm));
  e.motion.domain.cells[1] = static_cast<int>(k.cells_y.read(dm));
  e.motion.domain.cells[2] = static_cast<int>(k.cells_z.read(dm));
  const int min_cells = static_cast<int>(k.min_cells_per_wavelength.read(dm));
  if (sound_on) {
    if (!near_integer(Lx / lam_w, 1e-6))
      k.length_x.reject(dm, fmt::format("must be a whole number of wavelengths (c/f = {:.6g} m) for the periodic "
                                        "travelling wave", lam_w));
    const double per_wl = e.motion.domain.cells[0] / std::round(Lx / lam_w);
    if (per_wl < min_cells)
      k.cells_x.reject(dm, fmt::format("gives {:g} cells per wavelength; cells must resolve the wave "
                                       "({} = {})", per_wl, k.min_cells_per_wavelength.dotted(), min_cells));
  }
  check_cells(k, dm, e, dmax);
}

// [sampling]; after the domain and populations (the clone factor depends on the cell count).
void parse_sampling(const ConfigSection& root, AcousticCase& c) {
  const auto& k = keys().sampling;
  ConfigSection s = k.t.open(root);
  SamplingSettings& ss = c.engine.sampling;
  ss.placement = k.placement.read(s) == "random" ? Placement::random : Placement::stratified;
  ss.min_samples_per_cell = k.min_samples_per_cell.read(s);
  const std::size_t n = sample_count_after_cloning(c);
  double requested = 0.0;
  for (const auto& p : c.engine.populations) requested += static_cast<double>(p.samples);
  if (requested > kMaxSamplesAfterCloning)  // too many before any cloning: the samples are the cause
    throw ConfigError(fmt::format("{}: key '{}': the populations request {:.0f} samples in all, more than the limit "
                                  "of {}", c.file, keys().population.samples.dotted(), requested,
                                  kMaxSamplesAfterCloning));
  if (n > static_cast<std::size_t>(kMaxSamplesAfterCloning))
    k.min_samples_per_cell.reject(s, fmt::format("gives {} samples after cloning in {} cells, more than the limit of {}",
                                                 n, c.engine.motion.domain.num_cells(), kMaxSamplesAfterCloning));
}

void parse_kernels(const ConfigSection& root, EngineSettings& e) {
  const auto& k = kernel_keys();
  ConfigSection s = k.t.open(root);
  e.kernel = read_kernels(s);
  e.motion.inertia_correction = k.inertia_correction.read(s);
  const auto fractal = std::find_if(e.populations.begin(), e.populations.end(),
                                    [](const PopulationSpec& p) { return p.structure.fractal; });
  if (fractal == e.populations.end()) return;
  for (const std::string& name : mechanism_names(e.kernel))
    for (std::string_view compact : KernelMechanisms::compact_spheres_only_names())
      if (name == compact)
        (e.kernel.model == name ? k.model : k.brownian)
            .reject(s, fmt::format("treats particles as compact spheres, but population '{}' has {} = \"{}\" "
                                   "(docs/acoustics.md §1.8)",
                                   fractal->name, keys().population.structure.dotted(), settings::kStructureFractal));
}

// An outcome model key (outcomes.dry_model, outcomes.wet_model) and its table file key (outcomes.table,
// outcomes.wet_table), both read only when set, so the resolved config of a case without them stays as it
// was. With model = "table" the table is loaded and checked here: unreadable or malformed (probabilities
// outside [0, 1] or not summing to 1, P_break > 0 without valid fragment statistics) is refused naming the
// file key. Returns the table, or null for the closed-form model.
std::shared_ptr<const OutcomeTable> parse_table_model(const ConfigSection& o, const std::string& case_file,
                                                      const settings::Choice& model, std::string_view table_name,
                                                      const settings::Text& file) {
  const bool table = model.present(o) && model.read(o) == table_name;
  if (!table) {
    if (file.present(o)) file.reject(o, fmt::format("is read only with {} = \"{}\"", model.dotted(), table_name));
    return nullptr;
  }
  if (!file.present(o)) file.missing(o, fmt::format("required with {} = \"{}\"", model.dotted(), table_name));
  std::filesystem::path path = file.read(o);
  if (path.is_relative() && !case_file.empty()) path = std::filesystem::path(case_file).parent_path() / path;
  OutcomeTable t;
  try {
    t = load_outcome_table(path);
  } catch (const io::NetcdfReadError& e) {
    file.reject(o, e.what());
  } catch (const std::invalid_argument& e) {
    file.reject(o, fmt::format("not an outcome table (docs/acoustics.md §1.7): {}", e.what()));
  }
  return std::make_shared<const OutcomeTable>(std::move(t));
}

void parse_outcome_models(const ConfigSection& o, const std::string& case_file, OutcomeParams& oc) {
  const auto& k = keys().outcomes;
  oc.dry_table = parse_table_model(o, case_file, k.dry_model, settings::kOutcomeTable, k.table);
  if (oc.dry_table) oc.dry_model = OutcomeModel::table;
  oc.wet_table = parse_table_model(o, case_file, k.wet_model, settings::kOutcomeTable, k.wet_table);
  if (oc.wet_table) oc.wet_model = OutcomeModel::table;
}

// Charge and permittivity enter only the lookup of an outcome table (dry or wet) with those axes
// (outcome_table.hpp): a population declaring them without such a table is refused naming its key. A table
// in use without those axes ignores them (as the closed-form critical velocities do).
void check_charged_populations(const ConfigSection& root, EngineSettings& e) {
  const auto& k = keys().population;
  const auto any_table = [&](const auto& has) {
    return (e.outcomes.dry_table && has(*e.outcomes.dry_table)) || (e.outcomes.wet_table && has(*e.outcomes.wet_table));
  };
  const bool charged = any_table([](const OutcomeTable& t) { return t.charged(); });
  const bool permittivity = any_table([](const OutcomeTable& t) { return t.has_axis(kPermittivityAxis); });
  const auto& oc = keys().outcomes;
  for (const ConfigSection& s : k.t.elements(root)) {
    if (k.charge_density.present(s) && !charged)
      k.charge_density.reject(s, fmt::format("charge enters only the lookup of an outcome table with axes '{}' and "
                                             "'{}' ({} or {} = \"{}\", docs/acoustics.md §1.7); this run has none",
                                             kOutcomeAxes[kCharge1Axis], kOutcomeAxes[kCharge2Axis],
                                             oc.dry_model.dotted(), oc.wet_model.dotted(), settings::kOutcomeTable));
    if (k.permittivity.present(s) && !permittivity)
      k.permittivity.reject(s, fmt::format("enters only the lookup of an outcome table with the axis '{}' "
                                           "(docs/acoustics.md §1.7); this run has none",
                                           kOutcomeAxes[kPermittivityAxis]));
  }
  if (permittivity)
    for (const PopulationSpec& p : e.populations) e.outcomes.permittivities.push_back(p.permittivity);
}

// population.fractal_law = "table": D_f and k_f from the dry outcome table's attributes (outcome_table.hpp);
// refused naming the key when the run has no table or its table records no law. Then the cells are checked
// again against the collision diameters of that law (check_cells ran with the compact ones).
void apply_table_fractal_law(const ConfigSection& root, EngineSettings& e) {
  const auto& k = keys().population;
  const OutcomeTable* t = e.outcomes.dry_model == OutcomeModel::table ? e.outcomes.dry_table.get() : nullptr;
  bool applied = false;
  for (const ConfigSection& s : k.t.elements(root))
    for (PopulationSpec& p : e.populations) {
      if (!p.structure.from_table || p.name != k.name.read(s)) continue;
      if (!(t && t->has_fractal_law()))
        k.fractal_law.reject(s, fmt::format("needs a dry outcome table ({} = \"{}\") with the attributes '{}' and "
                                            "'{}' (an aggregate table of agglo outcomes); {}",
                                            keys().outcomes.dry_model.dotted(), settings::kOutcomeTable,
                                            kFractalDimensionAttribute, kFractalPrefactorAttribute,
                                            t ? "this table has none" : "this run has no table"));
      p.structure.fractal_dimension = t->fractal_dimension;
      p.structure.fractal_prefactor = t->fractal_prefactor;
      applied = true;
    }
  if (!applied) return;
  double dmax = 0.0;
  for (const PopulationSpec& p : e.populations) dmax = std::max(dmax, largest_diameter(p));
  check_cells(keys().domain, keys().domain.t.open(root), e, dmax);
}

void parse_outcomes(const ConfigSection& root, const std::string& case_file, OutcomeParams& oc) {
  const auto& k = keys().outcomes;
  ConfigSection o = k.t.open(root);
  oc.always_coalesce = k.always_coalesce.read(o);
  oc.hamaker = k.hamaker.read(o);
  oc.z0 = k.contact_distance.read(o);
  oc.contact_pressure = k.contact_pressure.read(o);
  oc.restitution = k.restitution.read(o);
  oc.friction = k.friction.read(o);
  oc.liquid_viscosity = k.liquid_viscosity.read(o);
  oc.film_ratio = k.film_roughness_ratio.read(o);
  oc.solid_density = k.solid_density.read(o);
  oc.energy_compensation = k.energy_compensation.read(o);
  parse_outcome_models(o, case_file, oc);
}

void parse_output(const ConfigSection& root, double te, OutputSettings& os) {
  const auto& k = keys().output;
  ConfigSection out = k.t.open(root);
  const Range within_run = Range::closed(0.0, te);
  os.psd_times = k.psd_times.read_or(out, std::vector<double>{0.0, 0.25 * te, 0.5 * te, 0.75 * te, te}, within_run);
  os.psd_bins = static_cast<int>(k.psd_bins.read(out));
  os.psd_d_min = k.psd_d_min.read(out);
  os.psd_d_max = k.psd_d_max.read(out);
  if (os.psd_d_max <= os.psd_d_min) k.psd_d_max.reject(out, fmt::format("must exceed {}", k.psd_d_min.dotted()));
  os.efficiency_interval = k.efficiency_interval.read_or(out, te / 200.0);
  os.snapshot_times =
      k.snapshot_times.read_or(out, std::vector<double>{0.0, 0.125 * te, 0.25 * te, 0.5 * te}, within_run);
  os.snapshot_x_fraction = k.snapshot_x_fraction.read(out);
  os.plots = k.plots.read(out);
}

}  // namespace

AcousticCase parse_acoustic_case(Config& cfg) {
  AcousticCase c;
  c.file = cfg.file();
  ConfigSection root = cfg.root();
  EngineSettings& e = c.engine;
  e.seed = static_cast<std::uint64_t>(keys().top.seed.read(root));
  const bool sound_on = parse_gas_sound(root, e);
  parse_time(root, e);
  const double dmax = parse_populations(root, e);
  parse_domain(root, sound_on, dmax, e);
  parse_sampling(root, c);
  parse_kernels(root, e);
  parse_outcomes(root, c.file, e.outcomes);
  check_charged_populations(root, e);
  apply_table_fractal_law(root, e);
  parse_output(root, e.t_end, c.output);
  cfg.check_unknown_keys();
  return c;
}

}  // namespace agglo::acoustics
