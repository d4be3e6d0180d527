#include "agglo/electrostatics/bem/bem_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "agglo/core/cancel.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/electrostatics/bem/bem_operator.hpp"
#include "agglo/electrostatics/bem/patches.hpp"
#include "agglo/electrostatics/bem/sphere_triangulation.hpp"
#include "agglo/electrostatics/fmm/direct.hpp"
#include "agglo/electrostatics/gmres.hpp"
#include "agglo/electrostatics/validate_spheres.hpp"

namespace agglo::es {

namespace {

using constants::eps0;
using constants::pi;

class BemSolver final : public Solver {
 public:
  explicit BemSolver(const SolverOptions& o) : opt_(o), unit_(bem::fibonacci_sphere(o.patches_per_sphere)) {}
  std::string name() const override { return std::string(kBemSolver); }
  Solution solve(const Problem& p) override;
  std::vector<SurfaceSample> surface() const override { return surface_; }
  // The convex hull of the patch centres of each sphere (cached per patch count), indices offset
  // to surface(): body b's patch k is sample b * n + k.
  std::vector<std::array<int, 3>> surface_triangles() const override {
    const std::size_t np = unit_.size();
    if (surface_.empty() || np < 4 || surface_.size() % np != 0) return {};
    const auto& sphere = bem::fibonacci_sphere_triangles(static_cast<int>(np));
    std::vector<std::array<int, 3>> tri;
    tri.reserve(surface_.size() / np * sphere.size());
    for (std::size_t b = 0; b < surface_.size() / np; ++b) {
      const int off = static_cast<int>(b * np);
      for (const auto& t : sphere) tri.push_back({t[0] + off, t[1] + off, t[2] + off});
    }
    return tri;
  }
  WarmStart warm_start() const override { return {{static_cast<long long>(warm_spheres_)}, warm_}; }
  void set_warm_start(const WarmStart& w) override {
    warm_spheres_ = static_cast<std::size_t>(w.ints.at(0));
    warm_ = w.values;
  }

 private:
  std::vector<double> solve_bound_charge(bem::BemOperator& A, const std::vector<double>& rhs,
                                         const std::vector<double>& sigma0, const bem::PatchSet& ps,
                                         GmresResult& gr, bool& warm) const;
  SolverOptions opt_;
  std::vector<Vec3> unit_;       // patch directions (outward normals) on the unit sphere
  std::vector<double> warm_;     // sigma_b of the previous solve, for the warm start
  std::size_t warm_spheres_ = 0;
  std::vector<SurfaceSample> surface_;
};

// Right-hand side b = (1 - kbar) sigma_f - eps0 dk (E_f + E_ext).n at every patch.
std::vector<double> right_hand_side(const Problem& prob, const bem::PatchSet& ps) {
  const auto& S = prob.spheres;
  std::vector<double> rhs(ps.n);
  for (std::size_t i = 0; i < ps.n; ++i) {
    const int bi = ps.body[i];
    double en = 0.5 * ps.sigma_f[i] / eps0 + dot(prob.external_field, ps.nrm[i]);  // own sigma_f: PV field
    for (std::size_t k = 0; k < ps.nb; ++k) {
      if (static_cast<int>(k) == bi || S[k].charge == 0.0) continue;
      const Vec3 d = ps.pos[i] - S[k].center;
      en += S[k].charge * dot(d, ps.nrm[i]) / (4.0 * pi * eps0 * std::pow(norm2(d), 1.5));
    }
    rhs[i] = (1.0 - ps.kbar[i]) * ps.sigma_f[i] - eps0 * ps.dk[i] * en;
  }
  return rhs;
}

// Net bound charge of body b: q_b/kappa_0 - q_b (BSL eqs. 24-25), carried by a uniform density.
std::vector<double> uniform_bound_charge(const Problem& prob, const bem::PatchSet& ps) {
  const auto& S = prob.spheres;
  const double k0 = prob.medium_permittivity;
  std::vector<double> sigma0(ps.n);
  for (std::size_t i = 0; i < ps.n; ++i) {
    const Sphere& s = S[ps.body[i]];
    sigma0[i] = (s.charge / k0 - s.charge) / (4.0 * pi * s.radius * s.radius);
  }
  return sigma0;
}

// Force and torque on body b (about its centre) and its contribution 1/2 \int phi sigma_f dS to the
// energy, from the bound charge sigma_b, its potential/field sums phi_b, e_b at the patches
// (charges sigma_b a, all bodies) and q = sigma_b a; the own body's field is removed for the forces.
double body_force(const Problem& prob, const bem::PatchSet& ps, std::size_t b, const std::vector<double>& sigma_b,
                  const std::vector<double>& q, const std::vector<double>& phi_b, const std::vector<Vec3>& e_b,
                  Solution& sol) {
  const auto& S = prob.spheres;
  const double ke = 1.0 / (4.0 * pi * eps0);
  const std::size_t np = ps.np, i0 = b * np;
  std::span<const Vec3> bp(&ps.pos[i0], np);
  std::vector<Vec3> e_own;
  fmm::direct_sum(bp, bp, std::span<const double>(&q[i0], np), nullptr, &e_own);
  Vec3 F{}, M{};
  double phi_int = 0.0;
  for (std::size_t k = 0; k < np; ++k) {
    const std::size_t i = i0 + k;
    Vec3 E = ke * (e_b[i] - e_own[k]) + prob.external_field;
    double phi = ke * phi_b[i] + sigma_b[i] * std::sqrt(ps.area[i] / pi) / (2.0 * eps0) + ke * S[b].charge / S[b].radius;
    for (std::size_t c = 0; c < ps.nb; ++c) {
      if (c == b) continue;
      const Vec3 d = ps.pos[i] - S[c].center;
      const double r2 = norm2(d), r = std::sqrt(r2);
      E += (ke * S[c].charge / (r2 * r)) * d;
      phi += ke * S[c].charge / r;
    }
    const double dq = (ps.sigma_f[i] + sigma_b[i]) * ps.area[i];
    F += dq * E;
    M += cross(ps.pos[i] - S[b].center, dq * E);
    phi_int += ps.area[i] * phi;
  }
  sol.force[b] = prob.medium_permittivity * F;
  sol.torque[b] = prob.medium_permittivity * M;
  return 0.5 * ps.sigma_f[i0] * phi_int;
}

}  // namespace

// GMRES on the constrained subspace: P A P u = P rhs, sigma_b = sigma0 + P u; warm-started from the
// previous sigma_b when the number of spheres (hence patches) is unchanged.
std::vector<double> BemSolver::solve_bound_charge(bem::BemOperator& A, const std::vector<double>& rhs,
                                                  const std::vector<double>& sigma0, const bem::PatchSet& ps,
                                                  GmresResult& gr, bool& warm) const {
  const std::size_t N = ps.n;
  std::vector<double> u(N, 0.0);
  warm = warm_spheres_ == ps.nb && warm_.size() == N;
  if (warm) {
    for (std::size_t i = 0; i < N; ++i) u[i] = warm_[i] - sigma0[i];
    A.project(u);
  }
  std::vector<double> pv(N);
  LinearOperator op = [&](std::span<const double> in, std::span<double> out) {
    std::copy(in.begin(), in.end(), pv.begin());
    A.project(pv);
    A.apply(pv, out);
    A.project(out);
  };
  const int restart = std::min(opt_.max_iterations, 100);
  // Area-weighted inner product; explicit true residual at every restart and at the end.
  const GmresOptions go{opt_.tolerance, opt_.max_iterations, restart, true};
  gr = gmres(op, rhs, u, ps.area, go);
  if (!gr.converged)
    throw NumericalError(fmt::format("bem: GMRES did not converge within {} iterations (relative residual {:.3g} > "
                                     "tolerance {:.3g}; {} spheres, {} patches, matvec {})",
                                     opt_.max_iterations, gr.residual, opt_.tolerance, ps.nb, N, opt_.matvec));
  A.project(u);
  std::vector<double> sigma_b(N);
  for (std::size_t i = 0; i < N; ++i) sigma_b[i] = sigma0[i] + u[i];
  return sigma_b;
}

Solution BemSolver::solve(const Problem& prob) {
  const auto t0 = std::chrono::steady_clock::now();
  validate_spheres(prob);
  const std::size_t nb = prob.spheres.size();
  Solution sol;
  sol.force.assign(nb, Vec3{});
  sol.torque.assign(nb, Vec3{});
  sol.stats.degree = static_cast<int>(unit_.size());
  if (nb == 0) return sol;

  const bem::PatchSet ps = bem::make_patch_set(prob, unit_);
  const std::size_t N = ps.n;
  bem::BemOperator A(ps, opt_);
  poll_cancel();  // after the set-up (patches, FMM tree); GMRES polls after every matvec
  // rhs = P (b - A sigma0)
  std::vector<double> rhs = right_hand_side(prob, ps);
  const std::vector<double> sigma0 = uniform_bound_charge(prob, ps);
  if (std::any_of(sigma0.begin(), sigma0.end(), [](double v) { return v != 0.0; })) {
    std::vector<double> tmp(N);
    A.apply(sigma0, tmp);
    for (std::size_t i = 0; i < N; ++i) rhs[i] -= tmp[i];
  }
  A.project(rhs);
  GmresResult gr;
  bool warm = false;
  std::vector<double> sigma_b = solve_bound_charge(A, rhs, sigma0, ps, gr, warm);

  // Fields of the bound charge at the patches, then forces, torques and energy per body.
  std::vector<double> q(N), phi_b;
  for (std::size_t i = 0; i < N; ++i) q[i] = sigma_b[i] * ps.area[i];
  std::vector<Vec3> e_b;
  A.fields(q, &phi_b, &e_b);
  double energy = 0.0;
  for (std::size_t b = 0; b < nb; ++b) {
    poll_cancel();
    energy += body_force(prob, ps, b, sigma_b, q, phi_b, e_b, sol);
  }
  sol.energy = energy;

  surface_.resize(N);
  for (std::size_t i = 0; i < N; ++i)
    surface_[i] = SurfaceSample{ps.pos[i], ps.nrm[i], ps.area[i], ps.sigma_f[i], sigma_b[i], ps.body[i]};
  warm_ = std::move(sigma_b);
  warm_spheres_ = nb;

  sol.stats.iterations = gr.iterations;
  sol.stats.residual = gr.residual;
  sol.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  sol.stats.extra = {{"matvec", opt_.matvec},     {"fmm_order", A.fmm_order()},
                     {"patches", N},              {"matvecs", gr.matvecs},
                     {"warm_start", warm},        {"tolerance", opt_.tolerance}};
  if (A.uses_fmm()) sol.stats.extra["fmm_m2l_pairs"] = A.fmm_m2l_pairs();
  return sol;
}

std::unique_ptr<Solver> make_bem_solver(const SolverOptions& opt) {
  if (opt.patches_per_sphere < bem::kMinPatchesPerSphere)
    throw ConfigError("bem: patches_per_sphere must be >= " + std::to_string(bem::kMinPatchesPerSphere) + " (got " +
                      std::to_string(opt.patches_per_sphere) + ")");
  if (!(opt.tolerance > 0.0 && opt.tolerance < 1.0))
    throw ConfigError("bem: tolerance must be in (0, 1) (got " + std::to_string(opt.tolerance) + ")");
  if (opt.max_iterations < 1)
    throw ConfigError("bem: max_iterations must be >= 1 (got " + std::to_string(opt.max_iterations) + ")");
  if (opt.matvec != "fmm" && opt.matvec != "direct")
    throw ConfigError("bem: matvec must be \"fmm\" or \"direct\" (got \"" + opt.matvec + "\")");
  if (opt.fmm_order < 0 || opt.fmm_order > 40)
    throw ConfigError("bem: fmm_order must be 0 (auto) or 1..40 (got " + std::to_string(opt.fmm_order) + ")");
  if (opt.fmm_leaf_size < 1)
    throw ConfigError("bem: fmm_leaf_size must be >= 1 (got " + std::to_string(opt.fmm_leaf_size) + ")");
  return std::make_unique<BemSolver>(opt);
}

}  // namespace agglo::es
