#include "agglo/impact/intact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "agglo/dem/contact/jkr_normal.hpp"
#include "agglo/dem/contact/no_resistance.hpp"
#include "agglo/dem/contact/ruan_li_friction.hpp"
#include "agglo/impact/contact_barrier.hpp"

namespace agglo::impact {

namespace {

// A relative residual of the pair decomposition of the electrostatic forces above this: not internal
// pair forces (an applied field, a visible particle elsewhere).
constexpr double kPairResidual = 1e-3;
// A load of at least this fraction of F_C pushing a contact apart leaves too little of a barrier to trust
// the constant-load picture.
constexpr double kMaxPushLoad = 0.9;
// Bound A counts contacts over every split of the system in two: beyond this many particles it can no
// longer hold (the lowest break state has more contacts than any vibration can spare) and is not tried.
constexpr std::size_t kMostCountedParticles = 12;

// Condition 1 of intact.hpp; null when it holds.
const char* intact_model_obstacle(const dem::DemSystem& sys) {
  const auto& d = sys.params();
  if (!d.walls.empty()) return "walls";
  if (d.gas.enabled) return "gas drag";
  const auto& m = sys.contact_law().names();
  namespace c = dem::contact;
  if (m.normal != c::JkrNormal::name || m.tangential != c::RuanLiFriction::name || m.rolling != c::NoRolling::name ||
      m.twisting != c::NoTwisting::name)
    return "a contact model with stored tangential energy";
  return nullptr;
}

// Condition B2: the active contacts among the primaries join every pair of them.
const char* intact_clique(std::size_t n_agg, const std::vector<const dem::Pair*>& contacts) {
  return contacts.size() == n_agg * (n_agg - 1) / 2 ? nullptr : "the agglomerate is not a clique of contacts";
}

struct IntactBody {
  Vec3 x, v;           // centre of mass and its velocity
  double extent = 0.0; // largest distance of a surface point from x, with the deformation margin [m]
  double bare_extent = 0.0;  // the same without the margin [m]
};

// Condition 3: every other particle invisible, and it and the agglomerate pairwise out of reach for good.
const char* intact_outsiders(const dem::DemSystem& sys, std::size_t n_agg, const IntactBody& agg, bool es,
                             double kappa0) {
  const auto& p = sys.particles();
  for (const auto& pr : sys.pairs())
    if (pr.state.active && (pr.i >= n_agg || pr.j >= n_agg)) return "another particle touches";
  std::vector<IntactBody> bodies{agg};
  for (std::size_t k = n_agg; k < p.size(); ++k) {
    if (es && (p.q[k] != 0.0 || p.kappa[k] != kappa0)) return "another particle is electrostatically visible";
    bodies.push_back({p.x[k], p.v[k], p.r[k]});
  }
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = a + 1; b < bodies.size(); ++b) {
      const Vec3 dx = bodies[b].x - bodies[a].x, dv = bodies[b].v - bodies[a].v;
      if (dot(dx, dv) < 0.0 || norm(dx) <= bodies[a].extent + bodies[b].extent) return "a particle may come back";
    }
  return nullptr;
}

IntactBody agglomerate_body(const dem::Particles& p, std::size_t n_agg, const std::vector<const dem::Pair*>& contacts) {
  IntactBody b;
  double mass = 0.0;
  for (std::size_t k = 0; k < n_agg; ++k) {
    mass += p.m[k];
    b.x += p.m[k] * p.x[k];
    b.v += p.m[k] * p.v[k];
  }
  b.x /= mass;
  b.v /= mass;
  for (std::size_t k = 0; k < n_agg; ++k) b.extent = std::max(b.extent, norm(p.x[k] - b.x) + p.r[k]);
  b.bare_extent = b.extent;
  for (const auto* c : contacts) b.extent += 4.0 * c->jkr.deltaC;
  return b;
}

// Solves M x = b in place for a symmetric matrix M (n x n, row-major) by Cholesky, M = L L^T; false when
// M is not positive definite (a pivot <= 1e-12 of the largest diagonal entry: a rank-deficient system).
bool cholesky_solve(std::vector<double>& m, std::vector<double>& b, std::size_t n) {
  double dmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) dmax = std::max(dmax, m[i * n + i]);
  for (std::size_t j = 0; j < n; ++j) {
    double d = m[j * n + j];
    for (std::size_t k = 0; k < j; ++k) d -= m[j * n + k] * m[j * n + k];
    if (!(d > 1e-12 * dmax)) return false;
    m[j * n + j] = std::sqrt(d);
    for (std::size_t i = j + 1; i < n; ++i) {
      double v = m[i * n + j];
      for (std::size_t k = 0; k < j; ++k) v -= m[i * n + k] * m[j * n + k];
      m[i * n + j] = v / m[j * n + j];
    }
  }
  for (std::size_t i = 0; i < n; ++i) {  // L y = b
    for (std::size_t k = 0; k < i; ++k) b[i] -= m[i * n + k] * b[k];
    b[i] /= m[i * n + i];
  }
  for (std::size_t i = n; i-- > 0;) {  // L^T x = y
    for (std::size_t k = i + 1; k < n; ++k) b[i] -= m[k * n + i] * b[k];
    b[i] /= m[i * n + i];
  }
  return true;
}

// Condition 4: the tensions G_c (> 0 pulling the pair together) whose pair forces F_k = sum_c G_c e_c give
// the electrostatic forces on the primaries, by least squares through the normal equations
// (E^T E) G = E^T F (E the 3 n_agg x n_c matrix of the contact directions, +e_c on i and -e_c on j, so
// (E^T E)_cd = s_cd e_c . e_d over the shared sphere, s_cd = +-1); false when the residual is too large or
// the contact lines are linearly dependent (not decided; a clique's are independent unless degenerate).
bool intact_pair_loads(const dem::Particles& p, std::size_t n_agg, const std::vector<const dem::Pair*>& contacts,
                       const std::vector<Vec3>& force, std::vector<double>& loads) {
  double fmax = 0.0;
  for (std::size_t k = 0; k < n_agg; ++k) fmax = std::max(fmax, norm(force[k]));
  const std::size_t nc = contacts.size();
  loads.assign(nc, 0.0);
  if (!(fmax > 0.0)) return true;
  std::vector<Vec3> e(nc);
  for (std::size_t c = 0; c < nc; ++c) {
    const auto& pr = *contacts[c];
    e[c] = (p.x[pr.j] - p.x[pr.i]) / norm(p.x[pr.j] - p.x[pr.i]);  // i -> j: the pull on i
  }
  // column c of E: +e_c at sphere i, -e_c at sphere j
  const auto entry = [&](std::size_t c, std::size_t k) {
    return k == contacts[c]->i ? 1.0 : k == contacts[c]->j ? -1.0 : 0.0;
  };
  std::vector<double> m(nc * nc, 0.0);
  for (std::size_t c = 0; c < nc; ++c) {
    loads[c] = dot(e[c], force[contacts[c]->i]) - dot(e[c], force[contacts[c]->j]);
    for (std::size_t d = 0; d < nc; ++d) {
      const std::size_t i = contacts[d]->i, j = contacts[d]->j;  // the spheres column d is nonzero on
      m[c * nc + d] = (entry(c, i) * entry(d, i) + entry(c, j) * entry(d, j)) * dot(e[c], e[d]);
    }
  }
  if (!cholesky_solve(m, loads, nc)) return false;
  std::vector<Vec3> fit(n_agg);
  for (std::size_t c = 0; c < nc; ++c) {
    fit[contacts[c]->i] += loads[c] * e[c];
    fit[contacts[c]->j] -= loads[c] * e[c];
  }
  for (std::size_t k = 0; k < n_agg; ++k)
    if (norm(fit[k] - force[k]) > kPairResidual * fmax) return false;
  return true;
}

// Kinetic energy of particles [0, n) (or `members`) relative to their centre of mass, spins included [J].
double internal_kinetic(const dem::Particles& p, const std::vector<std::size_t>& members) {
  double mass = 0.0;
  Vec3 mom;
  for (std::size_t k : members) mass += p.m[k], mom += p.m[k] * p.v[k];
  const Vec3 v_cm = mom / mass;
  double e = 0.0;
  for (std::size_t k : members) e += 0.5 * p.m[k] * norm2(p.v[k] - v_cm) + 0.5 * p.I[k] * norm2(p.w[k]);
  return e;
}

// Most contacts k spheres can hold at once: every pair, and at most half a kissing bound per sphere.
int most_contacts(int k, int kissing) { return std::min(k * (k - 1) / 2, k * kissing / 2); }

// Kissing bound of spheres with radii in [r_min, r_max]: a touching sphere of radius >= r_min covers a
// cap of half-angle theta, sin theta = r_min / (r_max + r_min), of the largest one: at most
// 2 / (1 - cos theta) of them (14 for equal spheres).
int kissing_bound(const dem::Particles& p, const std::vector<std::size_t>& members) {
  double rmin = std::numeric_limits<double>::infinity(), rmax = 0.0;
  for (std::size_t k : members) rmin = std::min(rmin, p.r[k]), rmax = std::max(rmax, p.r[k]);
  const double sin_t = rmin / (rmax + rmin);
  return static_cast<int>(std::floor(2.0 / (1.0 - std::sqrt(1.0 - sin_t * sin_t))));
}

// Without electrostatics (intact.hpp, bound A): the energy above the lowest energy a state at a break can
// have besides its breaking contact, and the smallest energy to break one contact from its formation.
IntactBound contact_count_bound(const dem::DemSystem& sys, const std::vector<std::size_t>& members, double s) {
  IntactBound b;
  const auto& p = sys.particles();
  const int n = static_cast<int>(members.size()), kissing = kissing_bound(p, members);
  int split = 0;  // most contacts of a state cut in two parts
  for (int k = 1; k < n; ++k) split = std::max(split, most_contacts(k, kissing) + most_contacts(n - k, kissing));
  const double x0 = formation_x(), xb = break_x(s);
  double w_min = std::numeric_limits<double>::infinity(), d_max = 0.0;
  for (int a = 0; a < n; ++a)
    for (int c = a + 1; c < n; ++c) {
      const auto jkr = sys.jkr_for(static_cast<std::uint32_t>(members[a]), static_cast<std::uint32_t>(members[c]));
      w_min = std::min(w_min, (jkr_potential(xb) - jkr_potential(x0)) * jkr.Fc * jkr.deltaC);
      d_max = std::max(d_max, (jkr_potential(x0) - jkr_potential(1.0)) * jkr.Fc * jkr.deltaC);
    }
  std::vector<char> in(p.size(), 0);
  for (std::size_t k : members) in[k] = 1;
  b.energy = internal_kinetic(p, members) + split * d_max;
  for (const auto& pr : sys.pairs())
    if (pr.state.active && in[pr.i] && in[pr.j]) {
      const double delta = p.r[pr.i] + p.r[pr.j] - norm(p.x[pr.j] - p.x[pr.i]);
      const double x = pr.jkr.a_of_delta(delta, pr.state.a) / pr.jkr.a0;
      b.energy += (jkr_potential(x) - jkr_potential(x0)) * pr.jkr.Fc * pr.jkr.deltaC;
    }
  b.barrier = w_min;
  b.applies = true;
  return b;
}

// Kinetic energy the rigid rotation of a clique keeps (intact.hpp, B): (1 - eps) L^T I^-1 L / 2 with the
// angular momentum L about the centre of mass (spins included) and the inertia tensor I of the clique as
// a rigid body; eps bounds the growth of I by the contact deformations (extent margin `grow`) [J].
double locked_rotation(const dem::Particles& p, std::size_t n_agg, const IntactBody& agg, double grow) {
  std::vector<double> inertia(9, 0.0), l(3, 0.0);
  double rho = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < n_agg; ++k) {
    const Vec3 r = p.x[k] - agg.x, h = p.m[k] * cross(r, p.v[k] - agg.v) + p.I[k] * p.w[k];
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) inertia[3 * a + b] -= p.m[k] * r[a] * r[b];
      inertia[4 * a] += p.m[k] * norm2(r) + p.I[k];
      l[a] += h[a];
    }
    rho = std::min(rho, norm(r));
  }
  const double keep = rho / (rho + grow);
  std::vector<double> x = l;  // I^-1 L
  if (n_agg < 2 || !cholesky_solve(inertia, x, 3)) return 0.0;
  return 0.5 * keep * keep * (l[0] * x[0] + l[1] * x[1] + l[2] * x[2]);
}

// With electrostatics (intact.hpp, bound B): a clique under constant pair loads.
IntactBound loaded_clique_bound(const dem::DemSystem& sys, std::size_t n_agg,
                                const std::vector<const dem::Pair*>& contacts, const std::vector<double>& loads,
                                double s) {
  IntactBound b;
  const auto& p = sys.particles();
  std::vector<std::size_t> agg(n_agg);
  for (std::size_t k = 0; k < n_agg; ++k) agg[k] = k;
  const IntactBody body = agglomerate_body(p, n_agg, contacts);
  b.energy = internal_kinetic(p, agg) - locked_rotation(p, n_agg, body, body.extent - body.bare_extent);
  b.barrier = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const auto& pr = *contacts[c];
    const double scale = pr.jkr.Fc * pr.jkr.deltaC, l = loads[c] / pr.jkr.Fc;
    const LoadedContact lc = loaded_contact(l, s);
    const double delta = p.r[pr.i] + p.r[pr.j] - norm(p.x[pr.j] - p.x[pr.i]);
    const double x = pr.jkr.a_of_delta(delta, pr.state.a) / pr.jkr.a0;
    if (l <= -kMaxPushLoad || x < lc.x_peak) {
      b.failed = "a contact is pushed apart or past its barrier";
      return b;
    }
    b.energy += (loaded_potential(x, l) - loaded_potential(lc.x_min, l)) * scale;
    b.barrier = std::min(b.barrier, lc.barrier * scale);
  }
  b.applies = true;
  return b;
}

}  // namespace

IntactBound intact_bound(const dem::DemSystem& sys, std::size_t n_agg, const std::vector<Vec3>* es_force,
                         double kappa0) {
  IntactBound b;
  const auto& p = sys.particles();
  std::vector<const dem::Pair*> contacts;
  for (const auto& pr : sys.pairs())
    if (pr.state.active && pr.i < n_agg && pr.j < n_agg) contacts.push_back(&pr);
  const IntactBody agg = agglomerate_body(p, n_agg, contacts);
  const double s = sys.params().contact.break_rule == dem::BreakRule::marshall ? 1.0 : -dem::kDeltaAtMinForce;
  const char* failed = intact_model_obstacle(sys);
  const char* outside = failed ? failed : intact_outsiders(sys, n_agg, agg, es_force != nullptr, kappa0);
  if (!failed && !es_force) {  // bound A: the other particles join the system unless out of reach for good
    std::vector<std::size_t> members(outside ? p.size() : n_agg);
    for (std::size_t k = 0; k < members.size(); ++k) members[k] = k;
    if (members.size() <= kMostCountedParticles) b = contact_count_bound(sys, members, s);
    if (b.intact()) return b;
  }
  if (!failed) failed = outside;
  if (!failed) failed = intact_clique(n_agg, contacts);
  std::vector<double> loads(contacts.size(), 0.0);
  if (!failed && es_force && es_force->size() != p.size()) failed = "no electrostatic forces yet";
  if (!failed && es_force && !intact_pair_loads(p, n_agg, contacts, *es_force, loads))
    failed = "the electrostatic forces are not internal pair forces";
  if (!failed) return loaded_clique_bound(sys, n_agg, contacts, loads, s);
  if (b.applies) return b;  // bound A, not (yet) met
  b.failed = failed;
  return b;
}

}  // namespace agglo::impact
