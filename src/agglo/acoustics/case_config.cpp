#include "agglo/acoustics/case_config.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"

namespace agglo::acoustics {

namespace {

bool near_integer(double x, double tol = 1e-6) { return std::abs(x - std::round(x)) <= tol * std::max(1.0, std::abs(x)); }

PopulationSpec parse_population(const ConfigSection& s) {
  PopulationSpec p;
  p.name = s.string("name", std::nullopt);
  p.phase = s.choice("phase", std::nullopt, {"solid", "liquid"}) == "solid" ? Phase::solid : Phase::liquid;
  const std::string dist =
      s.choice("distribution", std::nullopt, {"lognormal", "monodisperse", "exponential", "table"});
  p.number_concentration = s.number("number_concentration", std::nullopt, Range::nonnegative("1/m^3"));
  p.density = s.number("density", p.phase == Phase::solid ? 2500.0 : 1000.0, Range::positive("kg/m^3"));
  p.samples = s.integer("samples", std::nullopt, 1, 100000000);
  p.conserving_rounding = s.choice("weight_rounding", "nearest", {"nearest", "conserving"}) == "conserving";
  if (dist == "lognormal") {
    p.distribution = Distribution::lognormal;
    p.geometric_mean_diameter = s.number("geometric_mean_diameter", std::nullopt, Range::positive("m"));
    p.geometric_std = s.number("geometric_std", std::nullopt, Range::closed(1.0, 1e3));
    p.bins = static_cast<int>(s.integer("bins", 40, 1, 100000));
    if (p.samples < p.bins) s.fail_value("samples", fmt::format("needs at least one sample per bin (bins = {})", p.bins));
  } else if (dist == "monodisperse") {
    p.distribution = Distribution::monodisperse;
    p.diameter = s.number("diameter", std::nullopt, Range::nonnegative("m"));
  } else if (dist == "exponential") {
    p.distribution = Distribution::exponential;
    p.mean_volume = s.number("mean_volume", std::nullopt, Range::positive("m^3"));
  } else {
    p.distribution = Distribution::table;
    p.table_diameters = s.numbers("table_diameters", std::nullopt, Range::positive("m"));
    p.table_fractions = s.numbers("table_fractions", std::nullopt, Range::nonnegative());
    if (p.table_diameters.empty()) s.fail_value("table_diameters", "needs at least one diameter");
    if (p.table_fractions.size() != p.table_diameters.size())
      s.fail_value("table_fractions", "needs one fraction per entry of table_diameters");
    double f = 0.0;
    for (double x : p.table_fractions) f += x;
    if (!(f > 0.0)) s.fail_value("table_fractions", "needs a positive sum");
  }
  return p;
}

}  // namespace

AcousticCase parse_acoustic_case(Config& cfg) {
  AcousticCase c;
  c.file = cfg.file();
  ConfigSection root = cfg.root();
  EngineSettings& e = c.engine;
  e.seed = static_cast<std::uint64_t>(root.integer("seed", 1, 0, INT64_MAX));

  // [gas]
  ConfigSection g = cfg.root().section("gas");
  const double T = g.number("temperature", 298.15, Range::positive("K"));
  const double P = g.number("pressure", 101325.0, Range::positive("Pa"));
  const bool gravity = g.boolean("gravity", true);
  std::optional<double> mu, lam;
  if (g.has("viscosity")) mu = g.number("viscosity", std::nullopt, Range::positive("Pa s"));
  if (g.has("mean_free_path")) lam = g.number("mean_free_path", std::nullopt, Range::positive("m"));
  e.motion.gas = Gas::air(T, P, gravity, mu, lam);

  // [sound]
  ConfigSection so = cfg.root().section("sound");
  const bool sound_on = so.boolean("enabled", true);
  const double L = so.number("level_db", 140.0, Range::any("dB"));
  const double f = so.number("frequency_hz", 2000.0, Range::positive("Hz"));
  e.motion.sound = Sound::make(e.motion.gas, sound_on, L, f);
  if (sound_on) {
    const double ua = Sound::amplitude(e.motion.gas, L);
    const double cmax = 0.1 * e.motion.gas.sound_speed;
    if (!(ua > 0.0) || ua > cmax)
      so.fail_value("level_db", fmt::format("gives u_amp = {:.4g} m/s; the linear travelling-wave model needs "
                                            "0 < u_amp <= 0.1 c = {:.4g} m/s (L <= {:.1f} dB)",
                                            ua, cmax, 20.0 * std::log10(cmax / Sound::amplitude(e.motion.gas, 0.0))));
  }

  // [time]
  ConfigSection ti = cfg.root().section("time");
  e.t_end = ti.number("end", std::nullopt, Range::positive("s"));
  e.collision_dt = ti.number("collision_dt", 1e-5, Range::positive("s"));
  e.motion_dt = ti.number("motion_dt", e.collision_dt, Range::positive("s"));
  if (e.motion_dt > e.collision_dt * (1.0 + 1e-12))
    ti.fail_value("motion_dt", fmt::format("must not exceed time.collision_dt = {:g} s", e.collision_dt));
  if (!near_integer(e.collision_dt / e.motion_dt, 1e-9))
    ti.fail_value("motion_dt", fmt::format("must divide time.collision_dt = {:g} s into a whole number of steps",
                                           e.collision_dt));
  if (!near_integer(e.t_end / e.collision_dt, 1e-6))
    ti.fail_value("end", fmt::format("must be a whole number of collision steps ({:g} s)", e.collision_dt));
  const std::string integ = ti.choice("integrator", "exact", {"exact", "explicit", "none"});
  e.motion.integrator = integ == "exact" ? Integrator::exact
                        : integ == "explicit" ? Integrator::explicit_euler
                                              : Integrator::none;
  const std::string iv = ti.choice("initial_velocity", "steady", {"steady", "gas", "rest"});
  e.initial_velocity = iv == "steady" ? InitialVelocity::steady : iv == "gas" ? InitialVelocity::gas : InitialVelocity::rest;
  e.strict_guard = ti.choice("nanbu_guard", "subcycle", {"subcycle", "strict"}) == "strict";
  e.max_subcycles = static_cast<std::uint64_t>(ti.integer("max_subcycles", 100000, 1, 1000000000));

  // [[population]]
  auto pops = cfg.root().tables("population");
  if (pops.empty()) root.fail("population", "at least one [[population]] table is required");
  double dmax = 0.0;
  for (auto& ps : pops) {
    PopulationSpec p = parse_population(ps);
    const bool empty = p.number_concentration == 0.0 ||
                       (p.distribution == Distribution::monodisperse && p.diameter == 0.0);
    if (empty) continue;  // a population with no particles (e.g. the "0 um" / "0 cm^-3" sweep point)
    if (p.distribution == Distribution::monodisperse) dmax = std::max(dmax, p.diameter);
    if (p.distribution == Distribution::lognormal)
      dmax = std::max(dmax, p.geometric_mean_diameter * std::pow(p.geometric_std, 3.5));
    if (p.distribution == Distribution::table)
      for (double d : p.table_diameters) dmax = std::max(dmax, d);
    e.populations.push_back(p);
  }

  // [domain]
  ConfigSection dm = cfg.root().section("domain");
  const double lam_w = e.motion.sound.wavelength;
  const double Lx = sound_on ? dm.number("length_x", lam_w, Range::positive("m"))
                             : dm.number("length_x", std::nullopt, Range::positive("m"));
  e.motion.domain.L[0] = Lx;
  e.motion.domain.L[1] = dm.number("length_y", 0.01, Range::positive("m"));
  e.motion.domain.L[2] = dm.number("length_z", 0.01, Range::positive("m"));
  e.motion.domain.cells[0] = static_cast<int>(dm.integer("cells_x", 100, 1, 100000000));
  e.motion.domain.cells[1] = static_cast<int>(dm.integer("cells_y", 1, 1, 100000000));
  e.motion.domain.cells[2] = static_cast<int>(dm.integer("cells_z", 1, 1, 100000000));
  const int min_cells = static_cast<int>(dm.integer("min_cells_per_wavelength", 100, 1, 100000000));
  if (sound_on) {
    if (!near_integer(Lx / lam_w, 1e-6))
      dm.fail_value("length_x", fmt::format("must be a whole number of wavelengths (c/f = {:.6g} m) for the periodic "
                                            "travelling wave", lam_w));
    const double per_wl = e.motion.domain.cells[0] / std::round(Lx / lam_w);
    if (per_wl < min_cells)
      dm.fail_value("cells_x", fmt::format("gives {:g} cells per wavelength; cells must resolve the wave "
                                           "(domain.min_cells_per_wavelength = {})", per_wl, min_cells));
  }
  const char* ck[3] = {"cells_x", "cells_y", "cells_z"};
  for (int k = 0; k < 3; ++k) {
    const double edge = e.motion.domain.L[k] / e.motion.domain.cells[k];
    if (edge <= dmax)
      dm.fail_value(ck[k], fmt::format("gives cell edge {:.4g} m, not larger than the largest particle ({:.4g} m): "
                                       "the cells do not fit", edge, dmax));
  }
  long total_samples = 0;
  for (const auto& p : e.populations) total_samples += p.samples;
  if (static_cast<long>(e.motion.domain.num_cells()) > std::max<long>(1, total_samples))
    dm.fail_value("cells_x", fmt::format("gives {} cells for {} sampled particles: the cells do not fit (need at "
                                         "least one sample per cell on average)",
                                         e.motion.domain.num_cells(), total_samples));

  // [kernels]
  ConfigSection k = cfg.root().section("kernels");
  KernelSettings& ks = e.kernel;
  ks.model = kernel_model_from_name(k.choice("model", "acoustic", {"acoustic", "constant", "additive", "brownian_fuchs"}));
  ks.orthokinetic = k.boolean("orthokinetic", true);
  ks.acoustic_wake = k.boolean("acoustic_wake", true);
  ks.radiation_pressure = k.boolean("radiation_pressure", true);
  ks.brownian = k.boolean("brownian", true);
  ks.brownian_form = k.choice("brownian_form", "continuum_slip", {"continuum_slip", "fuchs"}) == "fuchs"
                         ? BrownianForm::fuchs
                         : BrownianForm::continuum_slip;
  e.motion.inertia_correction = k.boolean("inertia_correction", true);
  ks.collision_efficiency = k.number("collision_efficiency", 1.0, Range::closed(0.0, 1.0));
  ks.exclude_same_population = k.boolean("exclude_same_population", false);
  if (ks.model == KernelModel::constant)
    ks.constant_coefficient = k.number("constant_coefficient", std::nullopt, Range::positive("m^3/s"));
  if (ks.model == KernelModel::additive)
    ks.additive_coefficient = k.number("additive_coefficient", std::nullopt, Range::positive("1/s"));

  // [outcomes]
  ConfigSection o = cfg.root().section("outcomes");
  OutcomeParams& oc = e.outcomes;
  oc.always_coalesce = o.boolean("always_coalesce", false);
  oc.hamaker = o.number("hamaker", 1e-19, Range::positive("J"));
  oc.z0 = o.number("contact_distance", 4e-10, Range::positive("m"));
  oc.contact_pressure = o.number("contact_pressure", 3e8, Range::positive("Pa"));
  oc.restitution = o.number("restitution", 0.6, Range::open_closed(0.0, 1.0));
  oc.friction = o.number("friction", 0.2, Range::nonnegative());
  oc.liquid_viscosity = o.number("liquid_viscosity", 8.9e-4, Range::positive("Pa s"));
  oc.film_ratio = o.number("film_roughness_ratio", 10.0, Range::open(1.0, 1e300));
  oc.solid_density = o.number("solid_density", 2500.0, Range::positive("kg/m^3"));
  oc.energy_compensation = o.boolean("energy_compensation", true);

  // [output]
  ConfigSection out = cfg.root().section("output");
  const double te = e.t_end;
  c.output.psd_times = out.numbers("psd_times", std::vector<double>{0.0, 0.25 * te, 0.5 * te, 0.75 * te, te},
                                   Range::closed(0.0, te, "s"));
  c.output.psd_bins = static_cast<int>(out.integer("psd_bins", 60, 1, 100000));
  c.output.psd_d_min = out.number("psd_d_min", 1e-8, Range::positive("m"));
  c.output.psd_d_max = out.number("psd_d_max", 1e-4, Range::positive("m"));
  if (c.output.psd_d_max <= c.output.psd_d_min) out.fail_value("psd_d_max", "must exceed output.psd_d_min");
  c.output.efficiency_interval = out.number("efficiency_interval", te / 200.0, Range::positive("s"));
  c.output.snapshot_times =
      out.numbers("snapshot_times", std::vector<double>{0.0, 0.125 * te, 0.25 * te, 0.5 * te}, Range::closed(0.0, te, "s"));
  c.output.snapshot_x_fraction = out.number("snapshot_x_fraction", 0.25, Range::open_closed(0.0, 1.0));
  c.output.plots = out.boolean("plots", true);

  cfg.check_unknown_keys();
  return c;
}

}  // namespace agglo::acoustics
