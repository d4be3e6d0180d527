#pragma once
// Deterministic sectional solution of a sectional case (case_config.hpp): the initial populations
// projected onto the pivots (initial.hpp), the kernel of the case evaluated once per pivot pair with the
// DSMC's own kernel mechanisms (acoustics/kernels/), the fixed-pivot equations (coagulation.hpp)
// advanced by the adaptive exponential integrator (stepper.hpp).
#include <vector>

#include "agglo/acoustics/samples.hpp"
#include "agglo/sectional/case_config.hpp"
#include "agglo/sectional/coagulation.hpp"
#include "agglo/sectional/grid.hpp"
#include "agglo/sectional/initial.hpp"
#include "agglo/sectional/stepper.hpp"

namespace agglo::sectional {

class SectionalSolver {
 public:
  explicit SectionalSolver(const SectionalCase& c);
  // Advances to t >= time() [s].
  void advance_to(double t);
  double time() const { return t_; }
  const Grid& grid() const { return grid_; }
  const std::vector<double>& n() const { return n_; }  // number concentration of each pivot [1/m^3]
  const Projection& initial() const { return initial_; }
  const StepStats& stats() const { return stepper_.stats(); }
  acoustics::Phase phase() const { return phase_; }
  double density() const { return density_; }  // [kg/m^3]
  double number() const;                       // sum N_i [1/m^3]
  double volume() const;                       // sum N_i x_i [m^3/m^3]

 private:
  friend class SolverCheckpoint;  // saves and restores n_, t_ and the stepper's state (checkpoint.hpp)
  Grid grid_;
  acoustics::Phase phase_;
  double density_;
  FixedPivotCoagulation coag_;
  Etd2Stepper stepper_;
  Projection initial_;
  std::vector<double> n_;
  double t_ = 0.0;
};

}  // namespace agglo::sectional
