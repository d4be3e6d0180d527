#include "agglo/impact/pair_table.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include "agglo/core/constants.hpp"

namespace agglo::impact {

bool PairKey::operator<(const PairKey& o) const {
  return std::tie(ri, rj, ki, kj, k0) < std::tie(o.ri, o.rj, o.ki, o.kj, o.k0);
}

PairTable::PairTable(const es::SolverOptions& opt, const PairKey& key, double h_min, double h_max, int n) : key_(key) {
  auto solver = es::make_solver(opt);
  const double q0 = 1e-14;  // unit charge of the fits [C]
  for (int k = 0; k < n; ++k) {
    double s = std::log(h_min) + (std::log(h_max) - std::log(h_min)) * k / (n - 1);
    double h = std::exp(s);
    double d = key.ri + key.rj + h;
    auto solve = [&](double ci, double cj, double& f, double& u) {
      es::Problem p;
      p.medium_permittivity = key.k0;
      p.spheres = {{{0, 0, 0}, key.ri, ci * q0, key.ki}, {{d, 0, 0}, key.rj, cj * q0, key.kj}};
      auto sol = solver->solve(p);
      f = sol.force[1].x / (q0 * q0);
      u = sol.energy / (q0 * q0);
    };
    double f10, u10, f01, u01, f11, u11;
    solve(1, 0, f10, u10);
    solve(0, 1, f01, u01);
    solve(1, 1, f11, u11);
    s_.push_back(s);
    h_.push_back(h);
    y_[0].push_back(f10);
    y_[1].push_back(f11 - f10 - f01);
    y_[2].push_back(f01);
    y_[3].push_back(u10);
    y_[4].push_back(u11 - u10 - u01);
    y_[5].push_back(u01);
  }
  // Monotone cubic Hermite slopes (Fritsch-Carlson).
  for (int c = 0; c < 6; ++c) {
    const auto& y = y_[c];
    std::vector<double> delta(n - 1);
    for (int k = 0; k + 1 < n; ++k) delta[k] = (y[k + 1] - y[k]) / (s_[k + 1] - s_[k]);
    auto& m = m_[c];
    m.assign(n, 0.0);
    m[0] = delta[0];
    m[n - 1] = delta[n - 2];
    for (int k = 1; k + 1 < n; ++k) m[k] = delta[k - 1] * delta[k] <= 0 ? 0.0 : 0.5 * (delta[k - 1] + delta[k]);
    for (int k = 0; k + 1 < n; ++k) {
      if (delta[k] == 0.0) {
        m[k] = m[k + 1] = 0.0;
        continue;
      }
      double a = m[k] / delta[k], b = m[k + 1] / delta[k];
      double r = a * a + b * b;
      if (r > 9.0) {
        double t = 3.0 / std::sqrt(r);
        m[k] = t * a * delta[k];
        m[k + 1] = t * b * delta[k];
      }
    }
  }
}

double PairTable::coulomb_force(double h, double qi, double qj) const {
  double d = key_.ri + key_.rj + h;
  return qi * qj / (4.0 * constants::pi * constants::eps0 * key_.k0 * d * d);
}

void PairTable::eval(double h, double qi, double qj, double& force, double& energy) const {
  const double w[3] = {qi * qi, qi * qj, qj * qj};
  if (h >= h_.back()) {
    // Point charges beyond the table, continuous with its last entry.
    double fl = 0, ul = 0;
    for (int c = 0; c < 3; ++c) {
      fl += w[c] * y_[c].back();
      ul += w[c] * y_[3 + c].back();
    }
    double d = key_.ri + key_.rj + h, dl = key_.ri + key_.rj + h_.back();
    force = coulomb_force(h, qi, qj) + (fl - coulomb_force(h_.back(), qi, qj)) * (dl * dl) / (d * d);
    energy = ul + qi * qj / (4.0 * constants::pi * constants::eps0 * key_.k0) * (1.0 / d - 1.0 / dl);
    return;
  }
  double s = std::log(std::max(h, h_.front()));
  std::size_t k = std::upper_bound(s_.begin(), s_.end(), s) - s_.begin();
  k = std::clamp<std::size_t>(k, 1, s_.size() - 1) - 1;
  double ds = s_[k + 1] - s_[k], t = (s - s_[k]) / ds;
  double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t), h01 = t * t * (3 - 2 * t),
         h11 = t * t * (t - 1);
  force = energy = 0.0;
  for (int c = 0; c < 6; ++c) {
    double v = h00 * y_[c][k] + h10 * ds * m_[c][k] + h01 * y_[c][k + 1] + h11 * ds * m_[c][k + 1];
    (c < 3 ? force : energy) += w[c % 3] * v;
  }
}

std::shared_ptr<const PairTable> pair_table(const es::SolverOptions& opt, const PairKey& key, double h_min,
                                            double h_max) {
  static std::mutex mtx;
  // Keyed on the complete solver settings (SolverOptions' defaulted comparison: every field).
  static std::map<std::tuple<PairKey, es::SolverOptions, double, double>, std::shared_ptr<const PairTable>> cache;
  auto ck = std::make_tuple(key, opt, h_min, h_max);
  std::lock_guard<std::mutex> lock(mtx);  // held while building: concurrent runs wait, no double work
  auto it = cache.find(ck);
  if (it != cache.end()) return it->second;
  auto table = std::make_shared<const PairTable>(opt, key, h_min, h_max, 97);
  return cache.emplace(ck, table).first->second;
}

}  // namespace agglo::impact
