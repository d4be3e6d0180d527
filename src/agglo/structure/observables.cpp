#include "agglo/structure/observables.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "agglo/core/cancel.hpp"
#include "agglo/structure/primaries.hpp"

namespace agglo::structure {

double rg_point_mass(const Aggregate& a) {
  Vec3 c;
  for (const auto& x : a.x) c += x;
  c /= static_cast<double>(a.size());
  double s = 0.0;
  for (const auto& x : a.x) s += dot(x - c, x - c);
  return std::sqrt(s / static_cast<double>(a.size()));
}

double rg_spheres(const Aggregate& a) {
  Vec3 c;
  double m = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double mk = a.r[k] * a.r[k] * a.r[k];
    c += mk * a.x[k];
    m += mk;
  }
  c /= m;
  double s = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k)
    s += a.r[k] * a.r[k] * a.r[k] * (dot(a.x[k] - c, a.x[k] - c) + 0.6 * a.r[k] * a.r[k]);
  return std::sqrt(s / m);
}

ContactScan scan_contacts(const Aggregate& a) {
  ContactScan s;
  s.contacts.coordination.assign(a.size(), 0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    poll_cancel();  // O(N) per primary: a cancelled check of a large structure stops here (core/cancel.hpp)
    for (std::size_t j = i + 1; j < a.size(); ++j) {
      const double reach = a.r[i] + a.r[j], rmin = std::min(a.r[i], a.r[j]);
      const double box = reach + 2.0 * kContactTolerance * rmin;  // no contact beyond it on any axis
      const Vec3 d = a.x[j] - a.x[i];
      if (std::abs(d.x) > box || std::abs(d.y) > box || std::abs(d.z) > box) continue;
      const double err = (norm(d) - reach) / rmin;
      if (err < -kContactTolerance) {
        if (!s.overlap || -err > s.overlap_depth) s.oi = i, s.oj = j, s.overlap_depth = -err;
        s.overlap = true;
      } else if (err <= kContactTolerance) {
        s.contacts.pairs.emplace_back(i, j);
        ++s.contacts.coordination[i];
        ++s.contacts.coordination[j];
        s.contacts.max_error = std::max(s.contacts.max_error, std::abs(err));
      }
    }
  }
  return s;
}

std::vector<int> coordination_histogram(const std::vector<int>& coordination) {
  const int top = coordination.empty() ? 0 : *std::max_element(coordination.begin(), coordination.end());
  std::vector<int> counts(static_cast<std::size_t>(top) + 1, 0);
  for (int c : coordination) ++counts[static_cast<std::size_t>(c)];
  return counts;
}

std::size_t connected_components(std::size_t n, const std::vector<std::pair<std::size_t, std::size_t>>& pairs) {
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto root = [&](std::size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  std::size_t components = n;
  for (const auto& [i, j] : pairs) {
    const std::size_t a = root(i), b = root(j);
    if (a != b) parent[a] = b, --components;
  }
  return components;
}

FractalFit fit_fractal(const std::vector<double>& n, const std::vector<double>& rg_over_a) {
  const std::size_t m = n.size();
  if (m < 3 || rg_over_a.size() != m) throw std::invalid_argument("fractal fit needs at least 3 aggregates");
  double sx = 0, sy = 0, sxx = 0, sxy = 0;  // x = ln N (exact), y = ln(R_g / abar) (scatters)
  for (std::size_t k = 0; k < m; ++k) {
    const double x = std::log(n[k]), y = std::log(rg_over_a[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double md = static_cast<double>(m), sxx_c = sxx - sx * sx / md;
  if (!(sxx_c > 0.0)) throw std::invalid_argument("fractal fit needs aggregates of at least two sizes");
  const double slope = (sxy - sx * sy / md) / sxx_c, intercept = (sy - slope * sx) / md;
  double rss = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    const double e = std::log(rg_over_a[k]) - intercept - slope * std::log(n[k]);
    rss += e * e;
  }
  FractalFit f;
  f.points = m;
  f.fractal_dimension = 1.0 / slope;
  f.fractal_prefactor = std::exp(-intercept / slope);
  f.dimension_stderr = std::sqrt(rss / (md - 2.0) / sxx_c) / (slope * slope);  // delta method
  return f;
}

}  // namespace agglo::structure

namespace agglo::structure {

namespace {
constexpr std::size_t kSmallestGrowthPrefix = 16;
}

std::optional<FractalFit> growth_fit(const Aggregate& a) {
  std::vector<double> n, rg;
  const double abar = geometric_mean(a.r);
  for (std::size_t m = a.size(); m >= kSmallestGrowthPrefix; m /= 2) {
    Aggregate prefix;
    prefix.x.assign(a.x.begin(), a.x.begin() + static_cast<std::ptrdiff_t>(m));
    prefix.r.assign(a.r.begin(), a.r.begin() + static_cast<std::ptrdiff_t>(m));
    n.push_back(static_cast<double>(m));
    rg.push_back(rg_point_mass(prefix) / abar);
  }
  if (n.size() < 3) return std::nullopt;
  return fit_fractal(n, rg);
}

Summary summarize(const Aggregate& a, const Contacts& contacts, bool growth_order) {
  Summary s;
  s.primaries = a.size();
  s.abar = geometric_mean(a.r);
  s.rg_point_mass = rg_point_mass(a);
  s.rg_spheres = rg_spheres(a);
  s.contacts = contacts;
  s.coordination_counts = coordination_histogram(contacts.coordination);
  s.mean_coordination = 2.0 * static_cast<double>(contacts.pairs.size()) / static_cast<double>(a.size());
  if (growth_order) s.growth = growth_fit(a);
  return s;
}

}  // namespace agglo::structure
