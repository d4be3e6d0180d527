#pragma once
// Collision kernel beta_ij [m^3/s] of the DSMC (docs/model.md §C.3): the sum of the mechanisms the
// case switches on, each in its own file under kernels/ with its bound next to it:
//   orthokinetic + gravitational settling   kernels/orthokinetic.hpp        (eq. 8)
//   acoustic wake effect                    kernels/acoustic_wake.hpp       (eq. 9)
//   mutual radiation pressure               kernels/radiation_pressure.hpp  (eq. 10)
//   Brownian, continuum + slip (or Fuchs)   kernels/brownian.hpp            (eq. 11)
//   Brownian, Fuchs transition regime       kernels/brownian_fuchs.hpp      (model option)
//   Brownian, PartMC's form (comparisons)   kernels/brownian_partmc.hpp     (model option)
//   test kernels: constant K0, additive B (v_i + v_j)   kernels/constant.hpp, kernels/additive.hpp
// The registry (kernels/registry.hpp) lists them in summation order. `bound*` give upper bounds of
// the kernel over the partners of a cell (majorant of the Nanbu guard, docs/model.md §C.4).
#include <string>
#include <string_view>
#include <vector>

#include "agglo/acoustics/gas.hpp"
#include "agglo/acoustics/kernels/registry.hpp"
#include "agglo/acoustics/samples.hpp"
#include "agglo/acoustics/sound.hpp"

namespace agglo::acoustics {

class Kernel {
 public:
  // Switches on the mechanisms named by mechanism_names(s).
  Kernel(const KernelSettings& s, const Gas& gas, const Sound& sound);
  const KernelSettings& settings() const { return s_; }
  // Names of the switched-on mechanisms, in summation order.
  std::vector<std::string_view> mechanisms() const { return m_.names(); }
  // Sum of the enabled kernels for samples i, j at centre distance r.
  double beta(const SampleSet& p, std::size_t i, std::size_t j, double r) const;
  // Upper bound of beta(i, j) over every j the cell bounds describe.
  double bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const;
  // Upper bound of beta over every pair of the cell.
  double bound_cell(const CellBounds& cb) const;
  // Per mechanism (binned selection): how many are switched on, the k-th one's beta, and every one's
  // upper bound over the pairs i in group a, j in group b (out[k], k < mechanism_count()).
  std::size_t mechanism_count() const { return m_.active(); }
  double mechanism_beta(std::size_t k, const SampleSet& p, std::size_t i, std::size_t j, double r) const {
    return m_.beta_of(k, p, i, j, r);
  }
  void mechanism_bounds(const CellBounds& a, const CellBounds& b, double* out) const { m_.bound_pair_all(a, b, out); }
  // Derived bound fields of a group after its includes (call before mechanism_bounds reads it).
  void prepare(CellBounds& cb) const { m_.prepare(cb); }
  bool needs_distance() const { return m_.needs().distance; }
  bool needs_thermal_speed() const { return m_.needs().thermal_speed; }  // CellBounds::cbar_max
  bool needs_volume() const { return m_.needs().volume; }                // CellBounds::vol_max

 private:
  KernelSettings s_;
  KernelMechanisms m_;
};

}  // namespace agglo::acoustics
