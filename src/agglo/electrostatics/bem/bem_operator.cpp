#include "agglo/electrostatics/bem/bem_operator.hpp"

#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::es::bem {

using constants::pi;

PatchSet make_patch_set(const Problem& prob, const std::vector<Vec3>& unit) {
  const auto& S = prob.spheres;
  const double k0 = prob.medium_permittivity;
  PatchSet ps;
  ps.nb = S.size();
  ps.np = unit.size();
  ps.n = ps.nb * ps.np;
  const std::size_t N = ps.n;
  ps.pos.resize(N);
  ps.nrm.resize(N);
  for (auto* v : {&ps.area, &ps.kbar, &ps.dk, &ps.self, &ps.sigma_f}) v->resize(N);
  ps.body.resize(N);
  for (std::size_t b = 0; b < ps.nb; ++b) {
    const double R = S[b].radius, a = 4.0 * pi * R * R / static_cast<double>(ps.np);
    for (std::size_t k = 0; k < ps.np; ++k) {
      const std::size_t i = b * ps.np + k;
      ps.pos[i] = S[b].center + R * unit[k];
      ps.nrm[i] = unit[k];
      ps.area[i] = a;
      ps.kbar[i] = 0.5 * (S[b].permittivity + k0);
      ps.dk[i] = k0 - S[b].permittivity;
      ps.self[i] = std::sqrt(a) / (4.0 * R * std::sqrt(pi));  // n.I_ii a_i, BSL eq. 55
      ps.sigma_f[i] = S[b].charge / (4.0 * pi * R * R);
      ps.body[i] = static_cast<int>(b);
    }
  }
  return ps;
}

BemOperator::BemOperator(const PatchSet& ps, const SolverOptions& opt)
    : ps_(ps), pts_(ps.pos), nrms_(ps.nrm), q_(ps.n), y_(ps.n) {
  if (opt.matvec == "fmm") {
    fmm::FmmOptions fo;
    order_ = opt.fmm_order > 0 ? opt.fmm_order : fmm::order_for_tolerance(0.1 * opt.tolerance);
    fo.order = order_;
    fo.leaf_size = opt.fmm_leaf_size;
    fmm_.emplace(ps.pos, fo);
  }
}

void BemOperator::apply(std::span<const double> x, std::span<double> out) {
  const std::size_t N = ps_.n;
  for (std::size_t i = 0; i < N; ++i) q_[i] = x[i] * ps_.area[i] / (4.0 * pi);
  // y_i = sum_{j != i} q_j (r_i - r_j).n_i / |r_i - r_j|^3
  if (fmm_) {
    fmm_->evaluate(q_, nullptr, &field_);
    for (std::size_t i = 0; i < N; ++i) y_[i] = dot(field_[i], ps_.nrm[i]);
  } else {
    fmm::direct_normal_field(pts_, nrms_, q_, y_);
  }
  for (std::size_t i = 0; i < N; ++i) out[i] = ps_.kbar[i] * x[i] + ps_.dk[i] * (y_[i] + ps_.self[i] * x[i]);
}

void BemOperator::project(std::span<double> v) const {
  const std::size_t np = ps_.np;
  for (std::size_t b = 0; b < ps_.nb; ++b) {
    double s = 0.0, w = 0.0;
    for (std::size_t i = b * np; i < (b + 1) * np; ++i) {
      s += ps_.area[i] * v[i];
      w += ps_.area[i];
    }
    const double m = s / w;
    for (std::size_t i = b * np; i < (b + 1) * np; ++i) v[i] -= m;
  }
}

void BemOperator::fields(std::span<const double> q, std::vector<double>* potential,
                         std::vector<Vec3>* field) const {
  if (fmm_)
    fmm_->evaluate(q, potential, field);
  else
    fmm::direct_sum(ps_.pos, ps_.pos, q, potential, field);
}

}  // namespace agglo::es::bem
