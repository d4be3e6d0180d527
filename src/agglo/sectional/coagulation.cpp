#include "agglo/sectional/coagulation.hpp"

namespace agglo::sectional {

FixedPivotCoagulation::FixedPivotCoagulation(const Grid& g,
                                             const std::function<double(std::size_t, std::size_t)>& beta)
    : m_(g.size()) {
  beta_.reserve(m_ * (m_ + 1) / 2);
  target_.reserve(m_ * (m_ + 1) / 2);
  for (std::size_t j = 0; j < m_; ++j)
    for (std::size_t k = j; k < m_; ++k) {
      beta_.push_back(beta(j, k));
      target_.push_back(g.split(g.x[j] + g.x[k]));
    }
}

void FixedPivotCoagulation::rates(const std::vector<double>& n, std::vector<double>& birth,
                                  std::vector<double>& loss) const {
  birth.assign(m_, 0.0);
  loss.assign(m_, 0.0);
  std::size_t q = 0;
  for (std::size_t j = 0; j < m_; ++j) {
    const double nj = n[j];
    double lj = 0.0;
    // Pair (j, j): rate beta N_j^2 / 2, each event takes two particles of pivot j.
    {
      const double b = beta_[q];
      lj += b * nj;
      const Split& s = target_[q];
      const double r = 0.5 * b * nj * nj;
      birth[s.lo] += s.a_lo * r;
      birth[s.hi] += (1.0 - s.a_lo) * r;
      ++q;
    }
    for (std::size_t k = j + 1; k < m_; ++k, ++q) {
      const double b = beta_[q], nk = n[k];
      lj += b * nk;
      loss[k] += b * nj;
      const Split& s = target_[q];
      const double r = b * nj * nk;
      birth[s.lo] += s.a_lo * r;
      birth[s.hi] += (1.0 - s.a_lo) * r;
    }
    loss[j] += lj;
  }
}

}  // namespace agglo::sectional
