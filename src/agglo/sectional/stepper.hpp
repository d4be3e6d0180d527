#pragma once
// Time integration of the fixed-pivot equations (coagulation.hpp), written dN/dt = -c N + F(N) with
// c = L(N_n), the loss rates at the start of the step, held for the step, and F = B(N) - (L(N) - c) N.
// The linear part is integrated exactly in the step (exponential time differencing, Cox & Matthews
// 2002, J. Comput. Phys. 176:430, scheme ETD2RK), so that pivots with a large loss rate and few
// particles do not limit the step:
//   a       = N_n e^(-c h) + F(N_n) phi1,                 phi1 = (1 - e^(-c h)) / c
//   N_(n+1) = a + (F(a) - F(N_n)) phi2,                   phi2 = (e^(-c h) - 1 + c h) / (c^2 h)
// Step control by step doubling: one step of h and two of h/2; their difference D (local error
// O(h^3)) is measured as err = max(sum |D_i| / sum N_i, sum x_i |D_i| / sum x_i N_i) (number and
// volume), a step is accepted when err <= tol, the result is the two half steps plus D/3 (Richardson),
// and the next step is h (tol / err)^(1/3) (0.9 safety, between 0.2 h and 2 h). Values below zero
// (round-off size) are set to 0.
#include <cstdint>
#include <vector>

#include "agglo/sectional/coagulation.hpp"

namespace agglo::sectional {

struct StepStats {
  std::uint64_t accepted = 0, rejected = 0;
  double h_min = 0.0, h_max = 0.0;  // smallest and largest accepted step [s]
};

class Etd2Stepper {
 public:
  // x: pivot volumes (weights of the volume error norm).
  Etd2Stepper(const FixedPivotCoagulation& coag, std::vector<double> x, double tolerance)
      : coag_(coag), x_(std::move(x)), tol_(tolerance) {}
  // Advances n from t to t_end (t_end > t) in accepted steps. Throws NumericalError on a
  // non-finite state or when the step shrinks below 1e-12 of the interval.
  void advance(std::vector<double>& n, double t, double t_end);
  const StepStats& stats() const { return stats_; }

 private:
  friend class SolverCheckpoint;  // saves and restores h_ and stats_ (checkpoint.hpp)
  // One ETD2RK step of size h from n into out.
  void step(const std::vector<double>& n, double h, std::vector<double>& out);
  // h, then two h/2, from n; the Richardson value into out; returns err.
  double trial(const std::vector<double>& n, double h, std::vector<double>& out);
  double first_step(const std::vector<double>& n);
  const FixedPivotCoagulation& coag_;
  std::vector<double> x_;
  double tol_;
  double h_ = 0.0;  // next step [s] (0 = not started)
  StepStats stats_;
  std::vector<double> c_, f0_, fa_, a_, birth_, full_, half_;
};

}  // namespace agglo::sectional
