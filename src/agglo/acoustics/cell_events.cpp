#include "agglo/acoustics/cell_events.hpp"

#include <cmath>

#include "agglo/acoustics/coulomb_launch.hpp"
#include "agglo/acoustics/fragments.hpp"
#include "agglo/acoustics/merge.hpp"
#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

namespace {

PairType pair_type(Phase a, Phase b) {
  if (a == Phase::liquid || b == Phase::liquid) return PairType::droplet;
  if (a == Phase::solid && b == Phase::solid) return PairType::dry;
  return PairType::wet;
}

// Unit normal from i to j at contact for a hard-sphere encounter with relative velocity G:
// uniform impact parameter over the collision disk (b^2 uniform), uniform azimuth.
Vec3 contact_normal(const Vec3& G, CounterRng& rng) {
  const double u1 = rng.uniform(), u2 = rng.uniform();
  const double g = norm(G);
  Vec3 e = g > 0.0 ? G / g : Vec3{1.0, 0.0, 0.0};
  // Orthonormal basis (a, b) perpendicular to e.
  Vec3 ref = std::abs(e.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  Vec3 a = cross(e, ref);
  a /= norm(a);
  const Vec3 b = cross(e, a);
  const double cth = std::sqrt(1.0 - u1), sth = std::sqrt(u1);
  const double ph = 2.0 * constants::pi * u2;
  return cth * e + sth * (std::cos(ph) * a + std::sin(ph) * b);
}

}  // namespace

CellEvents::CellEvents(SampleSet& p_, const std::uint32_t* idx_, std::size_t n_, const CollisionContext& ctx_,
                       CollisionStats& st_, CounterRng& rng_)
    : p(p_), idx(idx_), n(n_), ctx(ctx_), st(st_), rng(rng_), oc(*ctx_.outcomes) {}

// The cell's debtors as the step found them, listed at its first collision (debts change only in
// collisions, so these are the debts at the start of the step; most cells of a step have no collision).
void CellEvents::list_debtors() {
  debtors_listed_ = true;
  // debts are only paid back at rebounds; most cells have none (count_positive: SIMD lanes)
  if (oc.energy_compensation && !oc.always_coalesce && count_positive(p.debt.data(), idx, 0, n) > 0)
    for (std::size_t a = 0; a < n; ++a)
      if (p.debt[idx[a]] > 0.0) debtors.push_back(idx[a]);
}

// A sample whose weight dropped to 0 takes half of the heaviest sample of the cell.
void CellEvents::refill(std::size_t dead) {
  std::size_t best = dead;
  double wb = 1.0;
  for (std::size_t a = 0; a < n; ++a)
    if (p.w[idx[a]] > wb) {
      wb = p.w[idx[a]];
      best = idx[a];
    }
  if (best == dead) {
    ++st.dead;
    return;
  }
  const std::uint64_t keep_id = p.id[dead];
  p.copy_sample(best, dead);
  p.id[dead] = keep_id;
  p.w[best] = std::ceil(0.5 * wb);
  p.w[dead] = std::floor(0.5 * wb);
  p.debt[dead] = 0.0;
  p.debt_ref[dead] = 0.0;
  touched_.push_back(static_cast<std::uint32_t>(best));
  ++st.refills;
}

// Gives the first fitting split-merge debt back to the pair (i, j) as relative kinetic energy.
void CellEvents::compensate(std::size_t i, std::size_t j) {
  if (!oc.energy_compensation) return;
  for (std::size_t k = 0; k < debtors.size(); ++k) {
    const std::size_t h = debtors[k];
    if (!(p.debt[h] > 0.0)) continue;
    const double Mref = p.debt_ref[h];
    const double ri = p.w[i] * p.mass[i] / Mref, rj = p.w[j] * p.mass[j] / Mref;
    if ((ri > 0.5 && ri < 2.0) || (rj > 0.5 && rj < 2.0)) {
      if (add_relative_energy(p, i, j, p.debt[h])) {
        st.energy_returned += p.debt[h];
        p.debt[h] = 0.0;
      }
      return;
    }
  }
}

// Dry pair (i, j) at normal speed gn: sticks below the critical velocity, else bounces; or drawn from the
// dry outcome table. Wet pairs alike with the Ennis critical velocity or the wet table.
// Diameters are volume-equivalent (structure.hpp; the kernels' d in compact runs).
OutcomeQuery CellEvents::table_query(const OutcomeTable& t, std::size_t i, std::size_t j, double gn) const {
  OutcomeQuery q{gn, p.volume_diameter(i), p.volume_diameter(j)};
  if (p.carries_charge) {
    q.sigma_i = p.q[i] / (constants::pi * q.d_i * q.d_i);
    q.sigma_j = p.q[j] / (constants::pi * q.d_j * q.d_j);
  }
  if (!oc.permittivities.empty())
    q.permittivity = 0.5 * (oc.permittivities[static_cast<std::size_t>(p.pop[i])] +
                            oc.permittivities[static_cast<std::size_t>(p.pop[j])]);
  if (t.has_primary_radii()) {
    q.rp_i = p.query_primary_radius(i);
    q.rp_j = p.query_primary_radius(j);
  }
  return q;
}

CollisionOutcome CellEvents::table_outcome(const OutcomeTable& t, TableTally c, std::size_t i, std::size_t j,
                                           double gn) {
  table_speed_ = gn;
  if (p.carries_charge && t.has_launch_gap()) {  // the Coulomb work before the launch gap
    table_speed_ = coulomb_launch_speed(gn, p.q[i], p.q[j], p.mass[i], p.mass[j], p.volume_diameter(i),
                                        p.volume_diameter(j), t.launch_gap, t.medium_permittivity);
    if (table_speed_ < 0.0) {  // turned back before the launch separation: never touches, a bounce
      turned_back_ = true;
      ++c.turned_back;
      return CollisionOutcome::bounce;
    }
  }
  const OutcomeProbabilities pr = t.at(table_query(t, i, j, table_speed_));
  ++c.queries;
  if (pr.clamped) ++c.clamped;
  const double u = rng.uniform();
  if (u < pr.stick) return CollisionOutcome::stick;
  return u < pr.stick + pr.brk ? CollisionOutcome::brk : CollisionOutcome::bounce;
}

CollisionOutcome CellEvents::dry_outcome(std::size_t i, std::size_t j, double gn) {
  if (oc.dry_model == OutcomeModel::critical_velocity) {
    const double di = p.volume_diameter(i), dj = p.volume_diameter(j);
    return gn <= critical_velocity_dry(oc, di, dj, p.rho[i], p.rho[j]) ? CollisionOutcome::stick
                                                                        : CollisionOutcome::bounce;
  }
  return table_outcome(*oc.dry_table, {st.table_queries, st.table_clamped, st.table_turned_back}, i, j, gn);
}

CollisionOutcome CellEvents::wet_outcome(std::size_t i, std::size_t j, double gn) {
  if (oc.wet_model == OutcomeModel::critical_velocity)
    return gn <= critical_velocity_wet(oc, p.volume_diameter(i), p.volume_diameter(j)) ? CollisionOutcome::stick
                                                                                        : CollisionOutcome::bounce;
  return table_outcome(*oc.wet_table, {st.wet_table_queries, st.wet_table_clamped, st.wet_table_turned_back}, i, j,
                       gn);
}

void CellEvents::collide(std::size_t i, std::size_t j) {
  if (!debtors_listed_) list_debtors();
  ++st.collisions;
  touched_.push_back(static_cast<std::uint32_t>(i));
  touched_.push_back(static_cast<std::uint32_t>(j));
  const PairType type = pair_type(p.phase(i), p.phase(j));
  CollisionOutcome out = CollisionOutcome::stick;
  Vec3 nrm;
  double gn = 0.0;
  turned_back_ = false;
  if (!(oc.always_coalesce || type == PairType::droplet)) {
    const Vec3 G{p.vx[i] - p.vx[j], p.vy[i] - p.vy[j], p.vz[i] - p.vz[j]};
    nrm = contact_normal(G, rng);
    gn = dot(G, nrm);
    out = type == PairType::dry ? dry_outcome(i, j, gn) : wet_outcome(i, j, gn);
  }
  if (out == CollisionOutcome::stick) {
    ++st.coalescences[static_cast<int>(type)];
    coalesce_weighted(p, i, j, *ctx.gas, *ctx.sound);
    if (p.w[i] <= 0.0) refill(i);
    if (p.w[j] <= 0.0) refill(j);
  } else if (out == CollisionOutcome::brk) {  // only pairs drawn from a table (weights stay >= 1: no refill)
    ++st.breakups[static_cast<int>(type)];
    const OutcomeTable& t = type == PairType::dry ? *oc.dry_table : *oc.wet_table;
    break_weighted(p, i, j, t.fragments_at(table_query(t, i, j, table_speed_)), rng, *ctx.gas, *ctx.sound);
  } else {
    ++st.rebounds[static_cast<int>(type)];
    // a pair turned back by like charges: the central Coulomb force reverses the normal motion elastically;
    // wet pairs rebound with e_wet (eq. 24), also when drawn from a table
    const double e = turned_back_              ? 1.0
                     : type == PairType::dry ? oc.restitution
                                               : wet_restitution(oc, p.volume_diameter(i), p.volume_diameter(j), gn);
    const double dE = rebound_weighted(p, i, j, nrm, e, turned_back_ ? 0.0 : oc.friction);
    st.energy_lost += dE;
    if (dE > 0.0) debtors.push_back(static_cast<std::uint32_t>(p.w[i] > p.w[j] ? i : j));
    compensate(i, j);
  }
}

}  // namespace agglo::acoustics
