#include "agglo/electrostatics/config.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo::es {

EsConfig parse_electrostatics(const ConfigSection& s) {
  EsConfig ec;
  auto& o = ec.options;
  o.solver = s.choice("solver", "spectral", {"coulomb", "spectral", "bem"});
  ec.medium_permittivity = s.number("medium_permittivity", 1.0, Range::positive());
  ec.min_gap = s.number("min_gap", 0.01, Range::closed_open(0.0, 1.0));
  ec.update_fraction = s.number("update_fraction", 0.01, Range::open_closed(0.0, 1.0));
  ec.update_interval = static_cast<int>(s.integer("update_interval", 0, 0, 1000000000));
  ec.external_field = s.vec3("external_field", Vec3{0, 0, 0}, Range::any("V/m"));
  ec.force_scale_chi = s.boolean("force_scale_chi", false);
  ec.hold = s.choice("hold", std::string("constant"), {"constant", "pair_corrected"});
  o.max_degree = static_cast<int>(s.integer("max_degree", 0, 0, 200));
  o.target_accuracy = s.number("target_accuracy", 1e-4, Range::closed_open(1e-12, 1.0));
  o.max_degree_limit = static_cast<int>(s.integer("max_degree_limit", 80, 2, 200));
  o.patches_per_sphere = static_cast<int>(s.integer("patches_per_sphere", 2000, 12, 10000000));
  o.tolerance = s.number("tolerance", 1e-6, Range::open(0.0, 1.0));
  o.max_iterations = static_cast<int>(s.integer("max_iterations", 200, 1, 100000));
  o.matvec = s.choice("matvec", "fmm", {"fmm", "direct"});
  o.fmm_order = static_cast<int>(s.integer("fmm_order", 0, 0, 40));
  o.fmm_leaf_size = static_cast<int>(s.integer("fmm_leaf_size", 64, 1, 100000));
  if (o.max_degree > 0 && o.max_degree > o.max_degree_limit)
    s.fail_value("max_degree", fmt::format("must not exceed max_degree_limit = {}", o.max_degree_limit));
  return ec;
}

namespace {
template <class Err>
void check_impl(const Problem& p, const std::string& what) {
  const int n = static_cast<int>(p.spheres.size());
  if (!(p.medium_permittivity > 0))
    throw Err(fmt::format("{}: medium permittivity must be > 0 (got {})", what, p.medium_permittivity));
  for (int i = 0; i < n; ++i) {
    const auto& s = p.spheres[i];
    if (!(s.radius > 0) || !std::isfinite(s.radius))
      throw Err(fmt::format("{}: particle {} has radius {} (must be > 0)", what, i, s.radius));
    if (!(s.permittivity > 0) || !std::isfinite(s.permittivity))
      throw Err(fmt::format("{}: particle {} has permittivity {} (must be > 0)", what, i, s.permittivity));
    if (!isfinite(s.center) || !std::isfinite(s.charge))
      throw Err(fmt::format("{}: particle {} has a non-finite position or charge", what, i));
  }
  for (int i = 0; i < n; ++i)
    for (int k = i + 1; k < n; ++k) {
      const auto& a = p.spheres[i];
      const auto& b = p.spheres[k];
      double d = norm(a.center - b.center);
      if (d <= a.radius + b.radius)
        throw Err(fmt::format(
            "{}: particles {} and {} overlap beyond the electrostatic regularisation (centre distance {:.6g} m <= "
            "r_E,{} + r_E,{} = {:.6g} m); separate them or raise min_gap",
            what, i, k, d, i, k, a.radius + b.radius));
    }
}
}  // namespace

void check_particles(const Problem& p, const std::string& what) { check_impl<ConfigError>(p, what); }

Problem make_problem(const EsConfig& ec, const std::vector<Vec3>& centers, const std::vector<double>& radii,
                     const std::vector<double>& charges, const std::vector<double>& permittivities) {
  const std::size_t n = centers.size();
  if (radii.size() != n || charges.size() != n || permittivities.size() != n)
    throw NumericalError("electrostatics: particle arrays of different lengths");
  Problem p;
  p.medium_permittivity = ec.medium_permittivity;
  p.external_field = ec.external_field;
  p.spheres.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    p.spheres[i] = {centers[i], electrostatic_radius(radii[i], ec.min_gap), charges[i], permittivities[i]};
  check_impl<NumericalError>(p, "electrostatics");
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
