#include "agglo/electrostatics/config.hpp"

#include <cmath>
#include <limits>
#include <string_view>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/core/settings.hpp"

namespace agglo::es {

EsConfig parse_electrostatics(const ConfigSection& s) {
  const auto& k = es_keys();
  EsConfig ec;
  auto& o = ec.options;
  o.solver = k.solver.read(s);
  ec.medium_permittivity = k.medium_permittivity.read(s);
  ec.min_gap = k.min_gap.read(s);
  ec.update_fraction = k.update_fraction.read(s);
  ec.update_interval = static_cast<int>(k.update_interval.read(s));
  ec.force_tolerance = k.force_tolerance.read(s);
  ec.external_field = k.external_field.read(s);
  ec.force_scale_chi = k.force_scale_chi.read(s);
  ec.hold = k.hold.read(s);
  o.max_degree = static_cast<int>(k.max_degree.read(s));
  o.target_accuracy = k.target_accuracy.read(s);
  o.max_degree_limit = static_cast<int>(k.max_degree_limit.read(s));
  o.far_field = k.far_field.read(s);
  if (k.preconditioner.present(s)) o.preconditioner = k.preconditioner.read(s);
  if (k.preconditioner_steps.present(s)) o.contact_low_steps = static_cast<int>(k.preconditioner_steps.read(s));
  o.patches_per_sphere = static_cast<int>(k.patches_per_sphere.read(s));
  o.tolerance = k.tolerance.read(s);
  o.max_iterations = static_cast<int>(k.max_iterations.read(s));
  o.matvec = k.matvec.read(s);
  o.fmm_order = static_cast<int>(k.fmm_order.read(s));
  o.fmm_leaf_size = static_cast<int>(k.fmm_leaf_size.read(s));
  if (o.max_degree > 0 && o.max_degree > o.max_degree_limit)
    k.max_degree.reject(s, fmt::format("must not exceed {} = {}", k.max_degree_limit.leaf(), o.max_degree_limit));
  return ec;
}

ParticleEntry parse_particle(const ConfigSection& element) {
  const auto& k = settings::electrostatics_settings().particles;
  ParticleEntry e;
  e.position = k.position.read(element);
  e.radius = k.radius.read(element);
  e.charge = k.charge.read(element);
  e.permittivity = k.permittivity.read(element);
  return e;
}

EsCase parse_electrostatics_case(Config& cfg) {
  const auto& keys = settings::electrostatics_settings();
  auto root = cfg.root();
  EsCase c;
  c.settings = parse_electrostatics(es_keys().t.open(root));
  auto elements = keys.particles.t.elements(root);
  if (elements.empty()) keys.particles.t.fail(root, "at least one [[particles]] entry is required");
  std::vector<Vec3> x;
  std::vector<double> r, q, kappa;
  for (const auto& el : elements) {
    const ParticleEntry e = parse_particle(el);
    x.push_back(e.position);
    r.push_back(e.radius);
    q.push_back(e.charge);
    kappa.push_back(e.permittivity);
  }
  c.surface_output = keys.output.surface.read(keys.output.t.open(root));
  cfg.check_unknown_keys();
  settings::check_as(keys.particles.t, root, [&] { c.problem = make_problem(c.settings, x, r, q, kappa); });
  return c;
}

namespace {
// The physical admissibility of the spheres (docs/model.md §B.3); throws NumericalError naming the particles.
void check_problem(const Problem& p, std::string_view what) {
  const int n = static_cast<int>(p.spheres.size());
  if (!(p.medium_permittivity > 0))
    throw NumericalError(fmt::format("{}: medium permittivity must be > 0 (got {})", what, p.medium_permittivity));
  for (int i = 0; i < n; ++i) {
    const auto& s = p.spheres[i];
    if (!(s.radius > 0) || !std::isfinite(s.radius))
      throw NumericalError(fmt::format("{}: particle {} has radius {} (must be > 0)", what, i, s.radius));
    if (!(s.permittivity > 0) || !std::isfinite(s.permittivity))
      throw NumericalError(fmt::format("{}: particle {} has permittivity {} (must be > 0)", what, i, s.permittivity));
    if (!isfinite(s.center) || !std::isfinite(s.charge))
      throw NumericalError(fmt::format("{}: particle {} has a non-finite position or charge", what, i));
  }
  for (int i = 0; i < n; ++i)
    for (int k = i + 1; k < n; ++k) {
      const auto& a = p.spheres[i];
      const auto& b = p.spheres[k];
      const double s = a.radius + b.radius;
      if (norm2(a.center - b.center) <= s * s)  // no square root per pair: the DEM coupling checks every solve
        throw NumericalError(fmt::format(
            "{}: particles {} and {} overlap beyond the electrostatic regularisation (centre distance {:.6g} m <= "
            "r_E,{} + r_E,{} = {:.6g} m); separate them or raise min_gap",
            what, i, k, norm(a.center - b.center), i, k, s));
    }
}
}  // namespace

void check_particles(const Problem& p, const std::string& what) {
  try {
    check_problem(p, what);
  } catch (const NumericalError& e) {
    throw ConfigError(e.what());
  }
}

void fill_problem(const EsConfig& ec, const std::vector<Vec3>& centers, const std::vector<double>& radii,
                  const std::vector<double>& charges, const std::vector<double>& permittivities, Problem& p) {
  const std::size_t n = centers.size();
  if (radii.size() != n || charges.size() != n || permittivities.size() != n)
    throw NumericalError("electrostatics: particle arrays of different lengths");
  p.medium_permittivity = ec.medium_permittivity;
  p.external_field = ec.external_field;
  p.spheres.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    p.spheres[i] = {centers[i], electrostatic_radius(radii[i], ec.min_gap), charges[i], permittivities[i]};
  check_problem(p, "electrostatics");
}

Problem make_problem(const EsConfig& ec, const std::vector<Vec3>& centers, const std::vector<double>& radii,
                     const std::vector<double>& charges, const std::vector<double>& permittivities) {
  Problem p;
  fill_problem(ec, centers, radii, charges, permittivities, p);
  return p;
}

double smallest_gap(const Problem& p) {
  double g = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.spheres.size(); ++i)
    for (std::size_t k = i + 1; k < p.spheres.size(); ++k)
      g = std::min(g, norm(p.spheres[i].center - p.spheres[k].center) - p.spheres[i].radius - p.spheres[k].radius);
  return g;
}

}  // namespace agglo::es
