#include "agglo/electrostatics/bem/bem_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/electrostatics/bem/patches.hpp"
#include "agglo/electrostatics/bem/sphere_triangulation.hpp"
#include "agglo/electrostatics/fmm/direct.hpp"
#include "agglo/electrostatics/fmm/fmm.hpp"
#include "agglo/electrostatics/gmres.hpp"

namespace agglo::es {

namespace {

using constants::eps0;
using constants::pi;

class BemSolver final : public Solver {
 public:
  explicit BemSolver(const SolverOptions& o) : opt_(o), unit_(bem::fibonacci_sphere(o.patches_per_sphere)) {}
  std::string name() const override { return "bem"; }
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

 private:
  SolverOptions opt_;
  std::vector<Vec3> unit_;       // patch directions (outward normals) on the unit sphere
  std::vector<double> warm_;     // sigma_b of the previous solve, for the warm start
  std::size_t warm_spheres_ = 0;
  std::vector<SurfaceSample> surface_;
};

void validate(const Problem& p) {
  if (!(p.medium_permittivity > 0.0) || !std::isfinite(p.medium_permittivity))
    throw ConfigError("bem: medium permittivity must be > 0 (got " + std::to_string(p.medium_permittivity) + ")");
  if (!isfinite(p.external_field)) throw ConfigError("bem: external field is not finite");
  const auto& s = p.spheres;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!(s[i].radius > 0.0) || !std::isfinite(s[i].radius))
      throw ConfigError("bem: sphere " + std::to_string(i) + " has radius " + std::to_string(s[i].radius) +
                        " (must be > 0)");
    if (!(s[i].permittivity > 0.0) || !std::isfinite(s[i].permittivity))
      throw ConfigError("bem: sphere " + std::to_string(i) + " has permittivity " +
                        std::to_string(s[i].permittivity) + " (must be > 0)");
    if (!isfinite(s[i].center) || !std::isfinite(s[i].charge))
      throw NumericalError("bem: sphere " + std::to_string(i) + " has a non-finite position or charge");
  }
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j)
      if (norm(s[i].center - s[j].center) <= s[i].radius + s[j].radius)
        throw NumericalError("bem: spheres " + std::to_string(i) + " and " + std::to_string(j) +
                             " overlap or touch (centre distance " + std::to_string(norm(s[i].center - s[j].center)) +
                             " m <= sum of radii " + std::to_string(s[i].radius + s[j].radius) +
                             " m); electrostatic radii must leave a gap");
}

}  // namespace

Solution BemSolver::solve(const Problem& prob) {
  const auto t0 = std::chrono::steady_clock::now();
  validate(prob);
  const auto& S = prob.spheres;
  const std::size_t nb = S.size();
  const std::size_t np = unit_.size();
  const std::size_t N = nb * np;
  const double k0 = prob.medium_permittivity;
  Solution sol;
  sol.force.assign(nb, Vec3{});
  sol.torque.assign(nb, Vec3{});
  sol.stats.degree = static_cast<int>(np);
  if (nb == 0) return sol;

  // ---- geometry and per-patch coefficients ----
  std::vector<Vec3> pos(N), nrm(N);
  std::vector<double> area(N), kbar(N), dk(N), self(N), sigma_f(N);
  std::vector<int> body(N);
  for (std::size_t b = 0; b < nb; ++b) {
    const double R = S[b].radius, a = 4.0 * pi * R * R / static_cast<double>(np);
    for (std::size_t k = 0; k < np; ++k) {
      const std::size_t i = b * np + k;
      pos[i] = S[b].center + R * unit_[k];
      nrm[i] = unit_[k];
      area[i] = a;
      kbar[i] = 0.5 * (S[b].permittivity + k0);
      dk[i] = k0 - S[b].permittivity;
      self[i] = std::sqrt(a) / (4.0 * R * std::sqrt(pi));  // n.I_ii a_i, BSL eq. 55
      sigma_f[i] = S[b].charge / (4.0 * pi * R * R);
      body[i] = static_cast<int>(b);
    }
  }
  const fmm::Points pts(pos), nrms(nrm);

  // ---- matrix-vector product A x ----
  const bool use_fmm = opt_.matvec == "fmm";
  std::optional<fmm::LaplaceFmm> fmm_op;
  int order = 0;
  if (use_fmm) {
    fmm::FmmOptions fo;
    order = opt_.fmm_order > 0 ? opt_.fmm_order : fmm::order_for_tolerance(0.1 * opt_.tolerance);
    fo.order = order;
    fo.leaf_size = opt_.fmm_leaf_size;
    fmm_op.emplace(pos, fo);
  }
  std::vector<double> q(N), y(N);
  std::vector<Vec3> field;
  // y_i = sum_{j != i} q_j (r_i - r_j).n_i / |r_i - r_j|^3
  auto normal_field = [&](std::span<const double> qq, std::span<double> out) {
    if (use_fmm) {
      fmm_op->evaluate(qq, nullptr, &field);
      for (std::size_t i = 0; i < N; ++i) out[i] = dot(field[i], nrm[i]);
    } else {
      fmm::direct_normal_field(pts, nrms, qq, out);
    }
  };
  auto apply_A = [&](std::span<const double> x, std::span<double> out) {
    for (std::size_t i = 0; i < N; ++i) q[i] = x[i] * area[i] / (4.0 * pi);
    normal_field(q, y);
    for (std::size_t i = 0; i < N; ++i) out[i] = kbar[i] * x[i] + dk[i] * (y[i] + self[i] * x[i]);
  };
  // Per-body area-weighted mean removal: the projector onto zero net bound charge per body.
  auto project = [&](std::span<double> v) {
    for (std::size_t b = 0; b < nb; ++b) {
      double s = 0.0, w = 0.0;
      for (std::size_t i = b * np; i < (b + 1) * np; ++i) {
        s += area[i] * v[i];
        w += area[i];
      }
      const double m = s / w;
      for (std::size_t i = b * np; i < (b + 1) * np; ++i) v[i] -= m;
    }
  };

  // ---- right-hand side b = (1 - kbar) sigma_f - eps0 dk (E_f + E_ext).n ----
  std::vector<double> rhs(N);
  for (std::size_t i = 0; i < N; ++i) {
    const int bi = body[i];
    double en = 0.5 * sigma_f[i] / eps0 + dot(prob.external_field, nrm[i]);  // own sigma_f: PV field
    for (std::size_t k = 0; k < nb; ++k) {
      if (static_cast<int>(k) == bi || S[k].charge == 0.0) continue;
      const Vec3 d = pos[i] - S[k].center;
      en += S[k].charge * dot(d, nrm[i]) / (4.0 * pi * eps0 * std::pow(norm2(d), 1.5));
    }
    rhs[i] = (1.0 - kbar[i]) * sigma_f[i] - eps0 * dk[i] * en;
  }
  // Net bound charge of body b: q_b/kappa_0 - q_b (BSL eqs. 24-25), carried by a uniform part.
  std::vector<double> sigma0(N);
  bool any_sigma0 = false;
  for (std::size_t i = 0; i < N; ++i) {
    sigma0[i] = (S[body[i]].charge / k0 - S[body[i]].charge) / (4.0 * pi * S[body[i]].radius * S[body[i]].radius);
    any_sigma0 = any_sigma0 || sigma0[i] != 0.0;
  }
  std::vector<double> tmp(N);
  if (any_sigma0) {
    apply_A(sigma0, tmp);
    for (std::size_t i = 0; i < N; ++i) rhs[i] -= tmp[i];
  }
  project(rhs);

  // ---- GMRES on the constrained subspace: P A P u = P (b - A sigma0) ----
  std::vector<double> u(N, 0.0);
  const bool warm = warm_spheres_ == nb && warm_.size() == N;
  if (warm) {
    for (std::size_t i = 0; i < N; ++i) u[i] = warm_[i] - sigma0[i];
    project(u);
  }
  std::vector<double> pv(N);
  LinearOperator op = [&](std::span<const double> in, std::span<double> out) {
    std::copy(in.begin(), in.end(), pv.begin());
    project(pv);
    apply_A(pv, out);
    project(out);
  };
  const int restart = std::min(opt_.max_iterations, 100);
  // Area-weighted inner product; explicit true residual at every restart and at the end.
  const GmresOptions go{opt_.tolerance, opt_.max_iterations, restart, true};
  const GmresResult gr = gmres(op, rhs, u, area, go);
  if (!gr.converged)
    throw NumericalError("bem: GMRES did not converge within " + std::to_string(opt_.max_iterations) +
                         " iterations (relative residual " + std::to_string(gr.residual) + " > tolerance " +
                         std::to_string(opt_.tolerance) + "; " + std::to_string(nb) + " spheres, " +
                         std::to_string(N) + " patches, matvec " + opt_.matvec + ")");
  project(u);
  std::vector<double> sigma_b(N);
  for (std::size_t i = 0; i < N; ++i) sigma_b[i] = sigma0[i] + u[i];

  // ---- fields of the bound charge at the patches; own-body part removed for forces ----
  for (std::size_t i = 0; i < N; ++i) q[i] = sigma_b[i] * area[i];
  std::vector<double> phi_b;
  std::vector<Vec3> e_b;
  if (use_fmm)
    fmm_op->evaluate(q, &phi_b, &e_b);
  else
    fmm::direct_sum(pos, pos, q, &phi_b, &e_b);
  const double ke = 1.0 / (4.0 * pi * eps0);
  double energy = 0.0;
  for (std::size_t b = 0; b < nb; ++b) {
    const std::size_t i0 = b * np;
    std::span<const Vec3> bp(&pos[i0], np);
    std::vector<Vec3> e_own;
    fmm::direct_sum(bp, bp, std::span<const double>(&q[i0], np), nullptr, &e_own);
    Vec3 F{}, M{};
    double phi_int = 0.0;
    for (std::size_t k = 0; k < np; ++k) {
      const std::size_t i = i0 + k;
      Vec3 E = ke * (e_b[i] - e_own[k]) + prob.external_field;
      double phi = ke * phi_b[i] + sigma_b[i] * std::sqrt(area[i] / pi) / (2.0 * eps0) +
                   ke * S[b].charge / S[b].radius;
      for (std::size_t c = 0; c < nb; ++c) {
        if (c == b) continue;
        const Vec3 d = pos[i] - S[c].center;
        const double r2 = norm2(d), r = std::sqrt(r2);
        E += (ke * S[c].charge / (r2 * r)) * d;
        phi += ke * S[c].charge / r;
      }
      const double dq = (sigma_f[i] + sigma_b[i]) * area[i];
      F += dq * E;
      M += cross(pos[i] - S[b].center, dq * E);
      phi_int += area[i] * phi;
    }
    sol.force[b] = k0 * F;
    sol.torque[b] = k0 * M;
    energy += 0.5 * sigma_f[i0] * phi_int;
  }
  sol.energy = energy;

  surface_.resize(N);
  for (std::size_t i = 0; i < N; ++i)
    surface_[i] = SurfaceSample{pos[i], nrm[i], area[i], sigma_f[i], sigma_b[i], body[i]};
  warm_ = std::move(sigma_b);
  warm_spheres_ = nb;

  sol.stats.iterations = gr.iterations;
  sol.stats.residual = gr.residual;
  sol.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  sol.stats.extra = {{"matvec", opt_.matvec},     {"fmm_order", order},
                     {"patches", N},              {"matvecs", gr.matvecs},
                     {"warm_start", warm},        {"tolerance", opt_.tolerance}};
  if (use_fmm) sol.stats.extra["fmm_m2l_pairs"] = fmm_op->lists().n_m2l;
  return sol;
}

std::unique_ptr<Solver> make_bem_solver(const SolverOptions& opt) {
  if (opt.patches_per_sphere < 4)
    throw ConfigError("bem: patches_per_sphere must be >= 4 (got " + std::to_string(opt.patches_per_sphere) + ")");
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
