#include "agglo/impact/experiment.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/electrostatic_coupling.hpp"
#include "agglo/impact/impact_run.hpp"
#include "agglo/core/constants.hpp"

namespace agglo::impact {

double radius_of_gyration(const dem::Particles& p, std::size_t n) {
  if (n == 0 || n > p.size()) n = p.size();
  Vec3 c;
  for (std::size_t k = 0; k < n; ++k) c += p.x[k];
  c /= static_cast<double>(n);
  double s = 0.0;
  for (std::size_t k = 0; k < n; ++k) s += norm2(p.x[k] - c);
  return std::sqrt(s / static_cast<double>(n));
}

// Adds the likely input cause to a DEM blow-up message.
void rethrow_with_cause(const dem::DemInstability& e) {
  const auto& k = impact_keys();
  throw dem::DemInstability(fmt::format("{}; likely input cause: {} too large for the contact stiffness, or an extreme "
                                        "{}, {} or {}",
                                        e.what(), k.time.dt.dotted(), k.material.density.dotted(),
                                        k.agglomerate.radius.dotted(), k.projectile.radius.dotted()));
}

namespace {

std::vector<std::vector<int>> components(const dem::DemSystem& sys) {
  const int n = static_cast<int>(sys.particles().size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (const auto& pr : sys.pairs())
    if (pr.state.active) parent[find(static_cast<int>(pr.i))] = find(static_cast<int>(pr.j));
  std::vector<std::vector<int>> groups;
  std::vector<int> slot(n, -1);
  for (int k = 0; k < n; ++k) {
    int r = find(k);
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[slot[r]].push_back(k);
  }
  return groups;
}

dem::Particles relax(const ImpactCase& c) {
  dem::DemSystem sys(build_agglomerate(c), c.dem);
  if (!c.electrostatics || c.time.relax_time <= 0.0) return sys.particles();
  auto es = make_electrostatic_force(c);
  sys.set_external_force(es.get());
  auto jkr = sys.jkr_for(0, 1);
  const double ke_tol = c.time.relax_energy * jkr.Fc * jkr.deltaC;
  const long max_steps = static_cast<long>(c.time.relax_time / sys.dt());
  for (long s = 0; s < max_steps; ++s) {
    sys.step();
    if (s > 100 && s % 50 == 0 && sys.kinetic_energy() < ke_tol) break;
  }
  sys.check_state();
  dem::Particles p = sys.particles();
  for (auto& v : p.v) v = {};
  for (auto& w : p.w) w = {};
  return p;
}

}  // namespace

ImpactOutcome classify(const dem::DemSystem& sys, std::size_t n_agg, double kappa0) {
  ImpactOutcome out;
  const auto& p = sys.particles();
  out.components = components(sys);
  // The component holding most original particles is the main body; others holding originals are fragments.
  auto originals = [&](const std::vector<int>& g) {
    return std::count_if(g.begin(), g.end(), [&](int k) { return static_cast<std::size_t>(k) < n_agg; });
  };
  std::size_t main = 0;
  for (std::size_t g = 1; g < out.components.size(); ++g)
    if (originals(out.components[g]) > originals(out.components[main])) main = g;
  bool all_escaping = true;
  for (std::size_t g = 0; g < out.components.size(); ++g) {
    if (g == main || originals(out.components[g]) == 0) continue;
    Fragment f;
    f.members = out.components[g];
    std::vector<char> in(p.size(), 0);
    for (int k : f.members) in[k] = 1;
    double mf = 0, mr = 0;
    Vec3 xf, xr, vf, vr;
    for (std::size_t k = 0; k < p.size(); ++k) {
      (in[k] ? mf : mr) += p.m[k];
      (in[k] ? xf : xr) += p.m[k] * p.x[k];
      (in[k] ? vf : vr) += p.m[k] * p.v[k];
    }
    xf /= mf, xr /= mr, vf /= mf, vr /= mr;
    Vec3 dx = xf - xr, dv = vf - vr;
    f.separation_rate = dot(dx, dv) / norm(dx);
    f.relative_ke = 0.5 * mf * mr / (mf + mr) * norm2(dv);
    double u = 0.0;
    for (std::size_t a = 0; a < p.size(); ++a)
      for (std::size_t b = 0; b < p.size(); ++b)
        if (in[a] && !in[b] && p.q[a] != 0.0 && p.q[b] != 0.0)
          u += p.q[a] * p.q[b] / (4.0 * constants::pi * constants::eps0 * kappa0 * norm(p.x[a] - p.x[b]));
    f.binding = std::max(0.0, -u);
    f.escaping = f.separation_rate > 0.0 && f.relative_ke > f.binding;
    all_escaping = all_escaping && f.escaping;
    out.fragments.push_back(f);
  }
  const bool split = !out.fragments.empty();
  out.broken = split && all_escaping;
  out.undecided = split && !all_escaping;
  return out;
}

dem::Particles relaxed_agglomerate(const ImpactCase& c) {
  try {
    return relax(c);
  } catch (const dem::DemInstability& e) {
    rethrow_with_cause(e);
  }
}

ImpactOutcome run_impact(const ImpactCase& c, double speed, Recorder* rec, const ProgressFn& progress,
                         const dem::Particles* relaxed) {
  ImpactRun run(c, relaxed ? *relaxed : relaxed_agglomerate(c), speed, rec, progress);
  return run.run();
}

}  // namespace agglo::impact
