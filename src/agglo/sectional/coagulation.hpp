#pragma once
// Fixed-pivot discretisation of the Smoluchowski equation (Kumar & Ramkrishna 1996) on a pivot grid
// (grid.hpp), for a kernel beta(x_j, x_k) [m^3/s] that depends on the sizes only:
//   dN_i/dt = sum_{j <= k} (1 - delta_jk/2) a_i(x_j + x_k) beta_jk N_j N_k  -  N_i sum_k beta_ik N_k
// with a_i(v) the split of a new particle of volume v onto the pivots around it (grid.hpp). Each
// coalescence removes two particles and adds one, shared so that number and volume are both kept
// (on the grid; a merger beyond the last pivot keeps its number there). N_i [1/m^3].
#include <cstddef>
#include <functional>
#include <vector>

#include "agglo/sectional/grid.hpp"

namespace agglo::sectional {

class FixedPivotCoagulation {
 public:
  // beta(j, k): the kernel of pivots j and k [m^3/s]; called once per pair j <= k.
  FixedPivotCoagulation(const Grid& g, const std::function<double(std::size_t, std::size_t)>& beta);

  // birth_i (first sum above) [1/(m^3 s)] and loss rate per particle L_i = sum_k beta_ik N_k [1/s].
  void rates(const std::vector<double>& n, std::vector<double>& birth, std::vector<double>& loss) const;
  std::size_t size() const { return m_; }

 private:
  std::size_t m_;
  // Pairs j <= k in the order j = 0.., k = j..: kernel beta_jk and the split of x_j + x_k.
  std::vector<double> beta_;
  std::vector<Split> target_;
};

}  // namespace agglo::sectional
