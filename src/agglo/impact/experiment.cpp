#include "agglo/impact/experiment.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iterator>
#include <numeric>

#include <fmt/format.h>

#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/electrostatic_coupling.hpp"
#include "agglo/impact/impact_run.hpp"
#include "agglo/core/cancel.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/settings_electrostatics.hpp"
#include "agglo/electrostatics/keys.hpp"

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
  return graph_components(sys.particles().size(), contact_edges(sys, sys.particles().size()));
}

std::string edge_list(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& e) {
  std::string s;
  for (std::size_t k = 0; k < e.size() && k < 3; ++k) s += fmt::format("{}{}-{}", k ? ", " : "", e[k].first, e[k].second);
  return e.size() > 3 ? s + ", ..." : s;
}

// The relaxation must leave the contact graph of the agglomerate as it was built: a field or charges
// that break or make contacts before the launch change the target the impact is meant to probe.
void check_relaxed_contacts(const dem::DemSystem& sys, const ImpactCase& c,
                            const std::vector<std::pair<std::uint32_t, std::uint32_t>>& before, double rg0) {
  const auto after = contact_edges(sys, sys.particles().size());
  if (after == before) return;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> broken, made;
  std::set_difference(before.begin(), before.end(), after.begin(), after.end(), std::back_inserter(broken));
  std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(made));
  const auto& es = es::solver_keys();
  const Vec3 e = c.coupling.es.external_field;
  const std::string cause =
      norm(e) > 0.0 ? fmt::format("the applied field {} = [{:g}, {:g}, {:g}] V/m (lower it)", es.external_field.dotted(),
                                  e.x, e.y, e.z)
                    : std::string("the particle charges (their repulsion exceeds the adhesion)");
  throw InvalidRunError(fmt::format(
      "the agglomerate's contact graph changed during the relaxation before the launch ({} of {} contacts broken{}{}, "
      "{} made{}{}; radius of gyration {:.3g} m -> {:.3g} m at t = {:.3g} s): the target is no longer the agglomerate "
      "of the case; likely cause: {}",
      broken.size(), before.size(), broken.empty() ? "" : ": ", edge_list(broken), made.size(),
      made.empty() ? "" : ": ", edge_list(made), rg0, radius_of_gyration(sys.particles()), sys.time(), cause));
}

bool relaxes(const ImpactCase& c) { return c.electrostatics && c.time.relax_time > 0.0; }

// The relaxation keeps the walls and the drag of still gas but no gravity or gas flow, which would
// move the body as a whole (docs/dem.md "Gas and walls"). `body`: the target, or an aggregate projectile.
dem::Particles relax(const ImpactCase& c, dem::Particles body, const ProgressFn& progress) {
  dem::DemParams still = c.dem;
  still.gravity = {};
  still.gas.flow = {};
  dem::DemSystem sys(std::move(body), still);
  if (!relaxes(c)) return sys.particles();
  auto es = make_electrostatic_force(c);
  sys.set_external_force(es.get());
  auto jkr = sys.jkr_for(0, sys.particles().size() > 1 ? 1 : 0);
  const double ke_tol = c.time.relax_energy * jkr.Fc * jkr.deltaC;
  const long max_steps = static_cast<long>(c.time.relax_time / sys.dt());
  // Progress after every step and, through the solvers' polls, during each electrostatic solve (the
  // heartbeat, core/cancel.hpp): a BEM solve of 30 spheres takes tens of seconds, and a report every 50
  // steps left the terminal silent for minutes.
  double fraction = 0.0;
  auto last = std::chrono::steady_clock::now();
  const std::function<void()> beat = [&] {
    if (heartbeat_due(last)) progress(fraction, sys.time());
  };
  const HeartbeatScope heartbeat(progress ? &beat : nullptr);
  sys.compute_forces();  // the first step's forces: contacts as built (the step reuses them)
  check_one_agglomerate(sys, sys.particles().size(), "as built, before the relaxation");
  const auto built = contact_edges(sys, sys.particles().size());
  const double rg0 = radius_of_gyration(sys.particles());
  for (long s = 0; s < max_steps; ++s) {
    poll_cancel();  // a step may hold a long electrostatic solve; the solvers poll too (core/cancel.hpp)
    sys.step();
    fraction = static_cast<double>(s + 1) / static_cast<double>(max_steps);
    if (progress && heartbeat_due(last)) progress(fraction, sys.time());
    if (s > 100 && s % 50 == 0 && sys.kinetic_energy() < ke_tol) break;
  }
  sys.check_state();
  check_relaxed_contacts(sys, c, built, rg0);
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

void check_one_agglomerate(const dem::DemSystem& sys, std::size_t n_agg, std::string_view when) {
  std::vector<std::vector<int>> parts;
  for (auto& g : components(sys))
    if (static_cast<std::size_t>(g.front()) < n_agg) parts.push_back(std::move(g));  // sorted: front() is the least
  if (parts.size() <= 1) return;
  std::sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a.size() < b.size(); });
  std::string members;
  for (std::size_t k = 0; k < parts.front().size() && k < 5; ++k) members += fmt::format("{}{}", k ? ", " : "", parts.front()[k]);
  if (parts.front().size() > 5) members += ", ...";
  const auto& particles = settings::electrostatics_settings().particles.t;
  throw InvalidRunError(fmt::format(
      "the target is not one agglomerate ({}): its contact graph has {} separate parts, the smallest of {} "
      "particle(s) (index {}) touching no other part; every particle must touch the rest (centre distance at most "
      "r_i + r_k; for a list agglomerate check the [[{}]] positions)",
      when, parts.size(), parts.front().size(), members, particles.name()));
}

dem::Particles relaxed_agglomerate(const ImpactCase& c, const ProgressFn& progress) {
  try {
    return relax(c, build_agglomerate(c), progress);
  } catch (const dem::DemInstability& e) {
    rethrow_with_cause(e);
  }
}

void relax_projectile(const ImpactCase& c, dem::Particles& p, std::size_t first, double speed) {
  if (c.projectile.shape == "sphere" || !relaxes(c) || first >= p.size()) return;
  dem::Particles body;
  for (std::size_t q = first; q < p.size(); ++q)
    body.add(p.x[q], p.r[q], material_density(c, p.mat[q]), {}, p.q[q], p.kappa[q], p.mat[q]);
  try {
    body = relax(c, std::move(body), {});
  } catch (const dem::DemInstability& e) {
    rethrow_with_cause(e);
  }
  for (std::size_t q = first; q < p.size(); ++q) {
    p.x[q] = body.x[q - first];
    p.v[q] = {speed, 0.0, 0.0};
    p.w[q] = {};
  }
}

ImpactOutcome run_impact(const ImpactCase& c, double speed, Recorder* rec, const ProgressFn& progress,
                         const dem::Particles* relaxed, ApproachCache* approach) {
  ImpactRun run(c, relaxed ? *relaxed : relaxed_agglomerate(c), speed, rec, progress);
  run.share_free_flight(approach);
  return run.run();
}

}  // namespace agglo::impact
