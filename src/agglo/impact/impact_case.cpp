#include "agglo/impact/impact_case.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/gas_law.hpp"
#include "agglo/core/settings_acoustic.hpp"
#include "agglo/dem/contact/settings.hpp"
#include "agglo/dem/neighbor_list.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/orientation.hpp"
#include "agglo/impact/structure_target.hpp"

namespace agglo::impact {

namespace {

// [material]; returns the real Young's modulus (0 = same as the model's).
double parse_material(const ConfigSection& root, ImpactCase& c) {
  const auto& km = impact_keys().material;
  auto mat = km.t.open(root);
  c.agglomerate.density = km.density.read(mat);
  auto& cp = c.dem.contact;
  cp.youngs_modulus = km.youngs_modulus.read(mat);
  cp.poisson_ratio = km.poisson_ratio.read(mat);
  cp.surface_energy = km.surface_energy.read(mat);
  cp.restitution = km.restitution.read(mat);
  cp.friction = km.friction.read(mat);
  return km.real_youngs_modulus.read(mat);
}

// [material] and [contact]; returns the real Young's modulus (0 = same as the model's).
double parse_material_contact(const ConfigSection& root, ImpactCase& c) {
  const double real_modulus = parse_material(root, c);
  const auto& kc = dem::contact::contact_settings();
  auto& cp = c.dem.contact;
  auto con = kc.t.open(root);
  cp.models = dem::contact::read_models(con);
  cp.declared = kc.read_declared(con);
  cp.rolling_angle = kc.rolling_angle.read(con);
  cp.break_rule = kc.break_rule.read(con) == "marshall" ? dem::BreakRule::marshall : dem::BreakRule::lammps;
  return real_modulus;
}

// Names a [[materials]] entry may not take: the default material and the wall's own choices.
constexpr std::array<std::string_view, 3> kReservedMaterialNames = {"default", "same", "rigid"};

// [[materials]]: the named materials, ids 1, 2, ... in the order of the entries; every value not given
// is the [material] one.
void parse_materials(const ConfigSection& root, ImpactCase& c) {
  const auto& k = impact_keys().materials;
  const auto& cp = c.dem.contact;
  for (const auto& e : k.t.elements(root)) {
    dem::Material m;
    m.name = k.name.read(e);
    if (std::find(kReservedMaterialNames.begin(), kReservedMaterialNames.end(), m.name) !=
        kReservedMaterialNames.end())
      k.name.reject(e, fmt::format("is reserved (default = the [material] table; same, rigid = {} choices)",
                                   impact_keys().wall.material.dotted()));
    for (const auto& other : c.dem.materials)
      if (other.name == m.name) k.name.reject(e, "is declared twice: each material needs a unique name");
    m.density = k.density.read_or(e, c.agglomerate.density);
    m.youngs_modulus = k.youngs_modulus.read_or(e, cp.youngs_modulus);
    m.poisson_ratio = k.poisson_ratio.read_or(e, cp.poisson_ratio);
    m.surface_energy = k.surface_energy.read_or(e, cp.surface_energy);
    m.restitution = k.restitution.read_or(e, cp.restitution);
    m.friction = k.friction.read_or(e, cp.friction);
    c.dem.materials.push_back(m);
  }
}

std::optional<std::uint32_t> find_material(const ImpactCase& c, std::string_view name) {
  if (name == "default") return 0;
  for (std::size_t k = 0; k < c.dem.materials.size(); ++k)
    if (c.dem.materials[k].name == name) return static_cast<std::uint32_t>(k + 1);
  return std::nullopt;
}

// The material id `key` names in `section`; `fallback` when the key is absent.
std::uint32_t read_material(const settings::Text& key, const ConfigSection& section, const ImpactCase& c,
                            std::uint32_t fallback) {
  if (!key.present(section)) return fallback;
  const auto id = find_material(c, key.read(section));
  if (!id) key.reject(section, fmt::format("unknown material; allowed: {}", material_names(c)));
  return *id;
}

void parse_time(const ConfigSection& root, ImpactCase& c) {
  const auto& k = impact_keys().time;
  auto ts = k.t.open(root);
  c.dem.dt = k.dt.read(ts);
  c.dem.steps_per_period = k.steps_per_period.read(ts);
  c.time.after_contact = k.after_contact.read(ts);
  c.time.max_approach = k.max_approach.read(ts);
  c.time.extension = k.extension.read(ts);
  c.time.max_extensions = static_cast<int>(k.max_extensions.read(ts));
  c.time.relax_time = k.relax_time.read(ts);
  c.time.relax_energy = k.relax_energy.read(ts);
  c.time.early_stop = k.early_stop.read(ts);
  c.time.early_stop_gap = k.early_stop_gap.read(ts);
  if (k.intact_stop.present(ts)) c.time.intact_stop = k.intact_stop.read(ts);
}

// [[particles]] entries of a list agglomerate may overlap by at most kMaxListOverlap times the JKR
// equilibrium overlap delta0 of their pair (touching at delta0 is the rest state); deeper overlaps
// start with a huge elastic energy (50 % overlap multiplies the kinetic energy by 1e6).
constexpr double kMaxListOverlap = 2.0;

void check_list_overlaps(const ConfigSection& root, const ImpactCase& c) {
  const auto& particles = settings::electrostatics_settings().particles.t;
  const auto& lp = c.agglomerate.particles;
  const dem::MaterialPairs mats(c.dem.contact, c.dem.materials);
  // Only overlapping pairs can exceed the bound: found by the DEM's cell grid in O(N) (skin 0: centre
  // distance below the sum of the radii), in the order (i, k) of an exhaustive scan.
  std::vector<Vec3> x;
  std::vector<double> r;
  for (const auto& e : lp) {
    x.push_back(e.position);
    r.push_back(e.radius);
  }
  dem::NeighborList overlapping;
  overlapping.build(x, r, 0.0, [](dem::Pair&) {});
  for (const auto& pair : overlapping.pairs()) {
    const std::size_t i = pair.i, k = pair.j;
    const double ri = lp[i].radius, rk = lp[k].radius;
    const double overlap = ri + rk - norm(lp[i].position - lp[k].position);
    const auto& cp = mats.at(c.agglomerate.material_of(i), c.agglomerate.material_of(k));
    const double delta0 = dem::JkrPair::make(ri * rk / (ri + rk), cp.estar(), cp.surface_energy).delta_equilibrium();
    if (!(overlap <= kMaxListOverlap * delta0))
      particles.fail(root, fmt::format("[[{}]] entries {} and {} overlap by {:.3g} m, more than {:g} x their JKR "
                                       "equilibrium overlap {:.3g} m; place touching particles at centre distance "
                                       "{:.6g} m",
                                       particles.name(), i, k, overlap, kMaxListOverlap, delta0, ri + rk - delta0));
  }
}

}  // namespace

AgglomerateSpec parse_agglomerate(const ConfigSection& root, const std::string& case_file, bool wall_impact) {
  const auto& ka = impact_keys().agglomerate;
  const auto& particles = settings::electrostatics_settings().particles.t;
  auto ag = ka.t.open(root);
  AgglomerateSpec a;
  a.shape = ka.shape.read(ag);
  a.radius = ka.radius.read(ag);
  a.charged = ka.charged.read(ag);
  a.charge_density = ka.charge_density.read(ag);
  a.permittivity = ka.permittivity.read(ag);
  if (a.shape == "list") {  // the entries carry their own charges and permittivities; a value other than
    // the default (which config.resolved.toml lists) would be ignored
    const settings::Setting* ignored = nullptr;
    if (a.permittivity != ka.permittivity.def()) ignored = &ka.permittivity;
    if (a.charge_density != ka.charge_density.def()) ignored = &ka.charge_density;
    if (a.charged != ka.charged.def()) ignored = &ka.charged;
    if (ignored)
      ignored->reject(ag, fmt::format("applies to the built-in shapes only; with {} = \"list\" each [[{}]] entry "
                                      "sets its own charge and permittivity",
                                      ka.shape.dotted(), particles.name()));
  }
  a.orientation = original_orientation(a.shape);
  if (ka.orientation.present(ag)) {  // read only when set, so the resolved config stays unchanged
    a.orientation = ka.orientation.read(ag);
    if (a.shape == "list" || is_structure_shape(a.shape))
      ka.orientation.reject(ag, fmt::format("applies to the tetrahedron and square only; {} = \"{}\" places the "
                                            "primaries as given",
                                            ka.shape.dotted(), a.shape));
  }
  parse_structure(ag, case_file, a);
  auto plist = particles.elements(root);
  if (a.shape == "list") {
    const std::size_t least = wall_impact ? 1 : 2;  // a single sphere may hit a wall
    if (plist.size() < least) {
      const std::string hint =
          wall_impact ? "" : fmt::format(" (one with {} = true)", impact_keys().wall.impact.dotted());
      ka.shape.reject(ag, fmt::format("shape = \"list\" needs at least {} [[{}]] entries{}", least == 1 ? "one" : "two",
                                      particles.name(), hint));
    }
    for (auto& ps : plist) a.particles.push_back(es::parse_particle(ps));
  } else if (!plist.empty()) {
    ka.shape.reject(ag, fmt::format("[[{}]] entries are only used with shape = \"list\"", particles.name()));
  }
  return a;
}

namespace {

// The materials of a structure file's material column (`file`: the key of the file, in `sec`).
void column_materials(const settings::Setting& file, const ConfigSection& sec, const ImpactCase& c,
                      AgglomerateSpec& a) {
  const auto& names = a.structure.material;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto id = find_material(c, names[k]);
    if (!id)
      file.reject(sec, fmt::format("primary {} (data row {}): unknown material \"{}\" in the material column; "
                                   "allowed: {}",
                                   k, k + 1, names[k], material_names(c)));
    a.materials.push_back(*id);
  }
}

// An aggregate projectile (projectile.shape other than "sphere"): its structure, orientation and materials.
void parse_projectile_body(const ConfigSection& pj, const std::string& case_file, ImpactCase& c) {
  const auto& kp = impact_keys().projectile;
  auto& p = c.projectile;
  if (kp.shape.present(pj)) p.shape = kp.shape.read(pj);
  p.body.shape = p.shape;
  p.body.radius = p.radius;
  p.body.permittivity = p.permittivity;
  p.body.material = p.material;
  parse_structure(pj, case_file, p.body, {kp.shape, kp.builder});  // refuses the builder keys with a sphere
  const bool aggregate = p.shape != "sphere";
  if (!aggregate && kp.orientation.present(pj))
    kp.orientation.reject(pj, fmt::format("applies to an aggregate projectile ({} other than \"sphere\")", kp.shape.dotted()));
  if (!aggregate) return;
  if (p.charge != 0.0)
    kp.charge.reject(pj, fmt::format("applies to a sphere projectile; an aggregate projectile takes the charge column of "
                                     "{} = \"file\"",
                                     kp.shape.dotted()));
  column_materials(kp.builder.file, pj, c, p.body);
  if (kp.orientation.present(pj) && kp.orientation.read(pj) == "random") p.rotation = projectile_orientation(c, 0);
}

// The materials of the agglomerate's primaries: agglomerate.material, particles.material of each
// [[particles]] entry, the material column of a structure file.
void parse_body_materials(const ConfigSection& root, ImpactCase& c) {
  const auto& ka = impact_keys().agglomerate;
  auto& a = c.agglomerate;
  auto ag = ka.t.open(root);
  a.material = read_material(ka.material, ag, c, 0);
  if (a.shape == "list") {
    const auto& kl = settings::electrostatics_settings().particles;
    for (const auto& e : kl.t.elements(root)) a.materials.push_back(read_material(kl.material, e, c, a.material));
  }
  column_materials(ka.file, ag, c, a);
}

// [agglomerate], [[particles]] (shape = "list") and [projectile].
void parse_bodies(const ConfigSection& root, const std::string& case_file, ImpactCase& c, bool one_sphere_target) {
  const double density = c.agglomerate.density;  // [material]
  c.agglomerate = parse_agglomerate(root, case_file, c.wall_impact || one_sphere_target);
  c.agglomerate.density = density;
  const auto& a = c.agglomerate;

  const auto& kp = impact_keys().projectile;
  auto pj = kp.t.open(root);
  auto& p = c.projectile;
  p.speed = kp.speed.read(pj);
  p.offset_radii = kp.offset_radii.read(pj);
  p.gap_radii = kp.gap_radii.read(pj);
  p.radius = kp.radius.read_or(pj, a.radius);
  p.charge = kp.charge.read(pj);
  p.permittivity = kp.permittivity.read(pj);
  parse_body_materials(root, c);
  p.material = read_material(kp.material, pj, c, c.agglomerate.material);
  parse_projectile_body(pj, case_file, c);
}

// [wall]: read only when present (cases without it resolve as before); the wall goes to c.dem.walls.
void parse_wall(const ConfigSection& root, ImpactCase& c) {
  const auto& kw = impact_keys().wall;
  if (!kw.t.present(root)) return;
  auto ws = kw.t.open(root);
  const bool on = kw.enabled.read(ws);
  dem::Wall w;
  w.point = kw.position.read(ws);
  const Vec3 n = kw.normal.read(ws);
  if (!(norm(n) > 0.0)) kw.normal.reject(ws, "must not be the zero vector");
  w.normal = n / norm(n);
  const std::string wm = kw.material.read(ws);
  w.material = wm == "rigid" ? dem::WallMaterial::rigid : wm == "same" ? dem::WallMaterial::same : dem::WallMaterial::named;
  if (w.material == dem::WallMaterial::named) {
    const auto id = find_material(c, wm);
    if (!id) kw.material.reject(ws, fmt::format("unknown material; allowed: \"same\", \"rigid\", {}", material_names(c)));
    w.material_id = *id;
  }
  const bool impact = kw.impact.read(ws);
  const bool grounded = kw.grounded.read(ws);
  if (!on) return;
  if (impact && !(w.normal.x < 0.0))
    kw.normal.reject(ws, fmt::format("with {} = true the agglomerate moves along +x: the wall must face it (a normal "
                                     "with a negative x component)",
                                     kw.impact.dotted()));
  c.dem.walls.push_back(w);
  c.wall_impact = impact;
  if (grounded) c.coupling.grounded.push_back(w);
}

// [gas] of an impact case (the keys of the acoustic cases' [gas], plus drag and flow): read only when
// present. Viscosity and mean free path default to air at the temperature and pressure (core/gas_law.hpp).
void parse_gas(const ConfigSection& root, ImpactCase& c) {
  const auto& kg = settings::acoustic_settings().gas;
  if (!kg.t.present(root)) return;
  auto gs = kg.t.open(root);
  const double T = kg.temperature.read(gs), P = kg.pressure.read(gs);
  const double mu = kg.viscosity.present(gs) ? kg.viscosity.read(gs) : gas::sutherland_viscosity(T);
  const double lambda = kg.mean_free_path.present(gs)
                            ? kg.mean_free_path.read(gs)
                            : gas::mean_free_path(mu, gas::density(T, P), gas::mean_speed(T));
  auto& g = c.dem.gas;
  g.enabled = kg.drag.read(gs);
  g.viscosity = mu;
  g.mean_free_path = lambda;
  g.flow = kg.flow.read(gs);
  if (kg.gravity.read(gs)) c.dem.gravity = {0.0, 0.0, -constants::g0};
}

// No particle of the launch configuration may reach through a wall by more than kMaxListOverlap times
// its JKR equilibrium overlap with it (touching at that overlap is a particle resting on the wall).
void check_walls(const ConfigSection& root, const ImpactCase& c) {
  if (c.dem.walls.empty()) return;
  dem::Particles p = build_agglomerate(c);
  if (!c.wall_impact) add_projectile(p, c, c.projectile.speed);
  const auto& kw = impact_keys().wall;
  const dem::MaterialPairs mats(c.dem.contact, c.dem.materials);
  const std::size_t n_agg = c.wall_impact ? p.size() : p.size() - 1;
  for (const auto& w : c.dem.walls)
    for (std::size_t q = 0; q < p.size(); ++q) {
      const double delta0 = dem::wall_jkr(w, mats, p.mat[q], p.r[q]).delta_equilibrium();
      const double overlap = p.r[q] - w.height(p.x[q]);
      if (!(overlap <= kMaxListOverlap * delta0))
        kw.position.reject(kw.t.open(root),
                           fmt::format("the wall plane cuts {} (centre [{:.4g}, {:.4g}, {:.4g}] m, radius {:.3g} m, "
                                       "{:.3g} m through the plane); place the wall outside the structure, on the side "
                                       "its normal points away from",
                                       q < n_agg ? fmt::format("particle {}", q) : std::string("the projectile"),
                                       p.x[q].x, p.x[q].y, p.x[q].z, p.r[q], overlap));
    }
}

// Smallest vcrit.tolerance accepted, relative to vcrit.v_max.
constexpr double kMinRelativeTolerance = 1e-9;

// [output], [vcrit] and [breakup].
void parse_searches(const ConfigSection& root, ImpactCase& c) {
  const auto& ko = impact_keys().output;
  auto out = ko.t.open(root);
  c.output.timeseries_interval = ko.timeseries_interval.read(out);
  c.output.snapshot_interval = ko.snapshot_interval.read(out);

  const auto& kv = impact_keys().vcrit;
  auto vc = kv.t.open(root);
  c.vcrit.v_min = kv.v_min.read(vc);
  c.vcrit.v_max = kv.v_max.read(vc);
  if (c.vcrit.v_max <= c.vcrit.v_min) kv.v_max.reject(vc, fmt::format("must be larger than {}", kv.v_min.dotted()));
  c.vcrit.scan_points = static_cast<int>(kv.scan_points.read(vc));
  c.vcrit.tolerance = kv.tolerance.read(vc);
  if (!(c.vcrit.tolerance >= kMinRelativeTolerance * c.vcrit.v_max))
    kv.tolerance.reject(vc, fmt::format("must be at least {:g} x {} = {:.3g} m/s (bisection below that resolves "
                                        "nothing physical and approaches the spacing of doubles)",
                                        kMinRelativeTolerance, kv.v_max.dotted(), kMinRelativeTolerance * c.vcrit.v_max));
  c.vcrit.points_per_round = static_cast<int>(kv.points_per_round.read(vc));
  if (kv.criterion.present(vc)) c.vcrit.sticking = kv.criterion.read(vc) == "sticking";
  if (kv.order.present(vc)) c.vcrit.top_down = kv.order.read(vc) == "top_down";

  const auto& kb = impact_keys().breakup;
  auto bu = kb.t.open(root);
  std::vector<double> grid(c.vcrit.scan_points);
  for (int k = 0; k < c.vcrit.scan_points; ++k)
    grid[k] = c.vcrit.v_min + (c.vcrit.v_max - c.vcrit.v_min) * k / (c.vcrit.scan_points - 1);
  c.breakup.speeds = kb.speeds.read_or(bu, grid);
  if (c.breakup.speeds.empty()) kb.speeds.reject(bu, "needs at least one speed");
  c.breakup.samples = static_cast<int>(kb.samples.read(bu));
  c.breakup.offset_spread = kb.offset_spread.read(bu);
  if (kb.orientations.present(bu)) c.breakup.orientations = static_cast<int>(kb.orientations.read(bu));
}

void parse_coupling(const ConfigSection& root, double real_modulus, ImpactCase& c) {
  const auto& a = c.agglomerate;
  bool any_charge = a.charged && a.charge_density > 0.0;
  for (const auto& lp : a.particles) any_charge = any_charge || lp.charge != 0.0;
  any_charge = any_charge || c.projectile.charge != 0.0;
  using Charges = const std::vector<double>*;  // the charge columns of structure files
  for (Charges s : std::initializer_list<Charges>{&a.structure.charge, &c.projectile.body.structure.charge})
    any_charge = any_charge || std::any_of(s->begin(), s->end(), [](double q) { return q != 0.0; });
  c.electrostatics = any_charge;
  const auto& ks = es::es_keys();
  if (!c.electrostatics && !ks.t.present(root)) return;
  c.coupling.es = es::parse_electrostatics(ks.t.open(root));
  if (c.coupling.es.force_scale_chi) {
    const auto& km = impact_keys().material;
    if (real_modulus <= 0.0)
      km.real_youngs_modulus.reject(km.t.open(root),
                                    fmt::format("{} = true needs the real modulus (> 0 Pa)", ks.force_scale_chi.dotted()));
    c.coupling.force_scale = std::pow(c.dem.contact.youngs_modulus / real_modulus, 0.4);
  }
  c.medium_permittivity = c.coupling.es.medium_permittivity;
  c.electrostatics = c.electrostatics || norm(c.coupling.es.external_field) > 0.0;
  if (!c.coupling.grounded.empty() && norm(c.coupling.es.external_field) > 0.0)
    ks.external_field.reject(ks.t.open(root), fmt::format("a grounded wall ({} = true) takes no applied field: the "
                                                          "images are those of a plane at zero potential without one",
                                                          impact_keys().wall.grounded.dotted()));
}

// Several orientations rotate one relaxed agglomerate rigidly (breakup.hpp), which is exact only when
// no external field acts on its relaxation.
void check_orientations(const ConfigSection& root, const ImpactCase& c) {
  if (c.breakup.orientations <= 1 || norm(c.coupling.es.external_field) == 0.0) return;
  const auto& kb = impact_keys().breakup;
  kb.orientations.reject(kb.t.open(root), fmt::format("more than one orientation needs {} = 0 (the relaxed "
                                                      "agglomerate is rotated rigidly, which an external field "
                                                      "would not leave in equilibrium)",
                                                      es::es_keys().external_field.dotted()));
}

// A time step set above dem::kMaxDtOverPeriod T0 (T0 of the launch configuration, agglomerate and
// projectile) resolves a contact by too few steps: refused before the run.
void check_time_step(const ConfigSection& root, const ImpactCase& c) {
  if (c.dem.dt <= 0.0) return;
  dem::Particles p = build_agglomerate(c);
  add_projectile(p, c, c.projectile.speed);
  const double t0 = dem::reference_period(p, c.dem);
  const double dt_max = dem::kMaxDtOverPeriod * t0;
  if (!(c.dem.dt <= dt_max)) {
    const auto& k = impact_keys().time;
    k.dt.reject(k.t.open(root), fmt::format("must be at most {:.3g} s = T0/{:g} (contact period T0 = {:.3g} s); "
                                            "set 0 for T0/{}",
                                            dt_max, 1.0 / dem::kMaxDtOverPeriod, t0, k.steps_per_period.leaf()));
  }
}

}  // namespace

double material_density(const ImpactCase& c, std::uint32_t id) {
  return id == 0 ? c.agglomerate.density : c.dem.materials[id - 1].density;
}

std::string material_name(const ImpactCase& c, std::uint32_t id) {
  return id == 0 ? std::string("default") : c.dem.materials[id - 1].name;
}

std::string material_names(const ImpactCase& c) {
  std::string out = "\"default\"";
  for (const auto& m : c.dem.materials) out += fmt::format(", \"{}\"", m.name);
  return out;
}

ImpactCase parse_impact_case(Config& cfg, bool one_sphere_target) {
  ImpactCase c;
  auto root = cfg.root();
  c.name = impact_keys().top.name.read(root);
  const double real_modulus = parse_material_contact(root, c);
  parse_materials(root, c);
  parse_time(root, c);
  parse_wall(root, c);
  parse_gas(root, c);
  parse_bodies(root, cfg.file(), c, one_sphere_target);
  parse_searches(root, c);
  parse_coupling(root, real_modulus, c);
  check_orientations(root, c);
  check_list_overlaps(root, c);
  check_walls(root, c);
  check_time_step(root, c);
  return c;
}

ImpactCase parse_aggregate_case(Config& cfg, bool& materials_given) {
  const auto& k = impact_keys();
  ImpactCase c;
  auto root = cfg.root();
  c.name = k.top.name.read(root);
  materials_given = k.material.t.present(root) || k.materials.t.present(root) ||
                    k.agglomerate.material.present(k.agglomerate.t.open(root));
  if (materials_given) {  // read only then, so that the resolved config of a case without them is unchanged
    (void)parse_material(root, c);
    parse_materials(root, c);
  }
  const double density = c.agglomerate.density;
  c.agglomerate = parse_agglomerate(root, cfg.file());
  c.agglomerate.density = density;
  materials_given = materials_given || !c.agglomerate.structure.material.empty();
  if (is_structure_shape(c.agglomerate.shape)) parse_body_materials(root, c);
  return c;
}

}  // namespace agglo::impact
