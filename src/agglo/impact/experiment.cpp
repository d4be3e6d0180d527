#include "agglo/impact/experiment.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/electrostatic_coupling.hpp"
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

io::ParticleSnapshot snapshot(const dem::DemSystem& sys) {
  const auto& p = sys.particles();
  return io::ParticleSnapshot{p.x, p.v, p.w, p.r, p.q, sys.contacts_per_particle()};
}

}  // namespace

// Broken, every fragment escaping, and every fragment's surfaces at least `min_gap` from the rest
// (beyond adhesive reach; its kinetic energy already exceeds its electrostatic binding).
bool clearly_broken(const dem::DemSystem& sys, std::size_t n_agg, double kappa0, double min_gap) {
  auto cl = classify(sys, n_agg, kappa0);
  if (!cl.broken) return false;
  const auto& p = sys.particles();
  for (const auto& f : cl.fragments) {
    std::vector<char> in(p.size(), 0);
    for (int k : f.members) in[k] = 1;
    for (std::size_t a = 0; a < p.size(); ++a)
      for (std::size_t b = 0; b < p.size(); ++b)
        if (in[a] && !in[b] && norm(p.x[a] - p.x[b]) - p.r[a] - p.r[b] < min_gap) return false;
  }
  return true;
}

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
  dem::Particles p = sys.particles();
  for (auto& v : p.v) v = {};
  for (auto& w : p.w) w = {};
  return p;
}

ImpactOutcome run_impact(const ImpactCase& c, double speed, Recorder* rec, const ProgressFn& progress,
                               const dem::Particles* relaxed) {
  dem::Particles agg = relaxed ? *relaxed : relaxed_agglomerate(c);
  const std::size_t n_agg = agg.size();
  dem::DemSystem sys(std::move(agg), c.dem);
  std::unique_ptr<dem::ExternalForce> es;
  if (c.electrostatics) {
    es = make_electrostatic_force(c);
    sys.set_external_force(es.get());
  }
  const double rp = c.agglomerate.radius;
  const double u0 = 2.0 * constants::pi * rp * rp * rp * c.agglomerate.charge_density * c.agglomerate.charge_density /
                    constants::eps0;
  const double t_launch = sys.time();
  {
    dem::Particles tmp = sys.particles();
    add_projectile(tmp, c, speed);
    sys.add_particle(tmp.x.back(), tmp.r.back(), c.agglomerate.density, tmp.v.back(), tmp.q.back(), tmp.kappa.back());
  }
  const std::size_t proj = n_agg;
  const double gap = c.projectile.gap_radii * rp;
  double max_approach = c.time.max_approach > 0.0 ? c.time.max_approach
                                                  : 5.0 * (gap + rp) / std::max(speed, 1e-3) + 1e-4;
  const double kappa0 = es ? c.medium_permittivity : 1.0;

  double next_row = 0.0, next_snap = 0.0;
  auto record = [&]() {
    if (!rec) return;
    double t = sys.time() - t_launch;
    if (t + 1e-15 >= next_row) {
      double ues = sys.external_energy();
      rec->rows.push_back({t, sys.kinetic_energy(), ues, u0 > 0 ? ues / u0 : 0.0,
                           radius_of_gyration(sys.particles()), radius_of_gyration(sys.particles(), n_agg),
                           sys.active_contacts()});
      next_row += c.output.timeseries_interval;
    }
    if (c.output.snapshot_interval > 0.0 && t + 1e-15 >= next_snap) {
      rec->snapshots.emplace_back(t, snapshot(sys));
      next_snap += c.output.snapshot_interval;
    }
  };

  ImpactOutcome out;
  out.speed = speed;
  out.dt = sys.dt();
  // Approach until first contact of the projectile.
  sys.compute_forces();  // contacts and electrostatic energy of the launch state
  record();
  auto projectile_touches = [&]() {
    for (const auto& pr : sys.pairs())
      if (pr.state.active && (pr.i == proj || pr.j == proj)) return true;
    return false;
  };
  while (sys.time() - t_launch < max_approach) {
    sys.step();
    record();
    if (progress && sys.steps() % 2000 == 0) progress(0.0, sys.time() - t_launch);
    if (projectile_touches()) {
      out.contact = true;
      break;
    }
  }
  out.t_contact = sys.time() - t_launch;
  if (out.contact) {
    double t_stop = sys.time() + c.time.after_contact;
    for (int ext = 0;; ++ext) {
      const double t_from = sys.time();
      bool decided_early = false;
      while (sys.time() < t_stop) {
        sys.step();
        record();
        if (progress && sys.steps() % 2000 == 0)
          progress((sys.time() - t_from) / (t_stop - t_from), sys.time() - t_launch);
        if (c.time.early_stop && sys.steps() % 500 == 0 && clearly_broken(sys, n_agg, kappa0, c.time.early_stop_gap * rp)) {
          decided_early = true;
          break;
        }
      }
      out.early_stop = decided_early;
      auto cl = classify(sys, n_agg, kappa0);
      out.broken = cl.broken;
      out.undecided = cl.undecided;
      out.components = cl.components;
      out.fragments = cl.fragments;
      out.extensions = ext;
      if (!cl.undecided || ext >= c.time.max_extensions) break;
      t_stop += c.time.extension;
    }
  } else {
    out.components = {};
  }
  out.t_end = sys.time() - t_launch;
  if (auto* ef = dynamic_cast<ElectrostaticForce*>(es.get())) {
    out.es_solves = ef->solves();
    out.es_seconds = ef->seconds();
  }
  out.steps = sys.steps();
  return out;
}

}  // namespace agglo::impact
