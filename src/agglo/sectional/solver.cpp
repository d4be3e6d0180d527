#include "agglo/sectional/solver.hpp"

#include <algorithm>

#include "agglo/acoustics/kernels.hpp"

namespace agglo::sectional {

namespace {
// The case's kernel at the pivots: one sample per pivot of the case's phase and density.
FixedPivotCoagulation coagulation(const Grid& g, const acoustics::EngineSettings& e) {
  const auto& gas = e.motion.gas;
  const auto& sound = e.motion.sound;
  const acoustics::PopulationSpec& pop = e.populations.front();
  const bool solid = pop.phase == acoustics::Phase::solid;
  acoustics::SampleSet p;
  for (double x : g.x) p.add(0.0, 0.0, 0.0, solid ? x : 0.0, solid ? 0.0 : x, pop.density * x, 1.0, 0, gas, sound);
  const acoustics::Kernel kernel(e.kernel, gas, sound);
  return FixedPivotCoagulation(g, [&](std::size_t j, std::size_t k) { return kernel.beta(p, j, k, 0.0); });
}
}  // namespace

SectionalSolver::SectionalSolver(const SectionalCase& c)
    : grid_(Grid::geometric(c.grid.d_min, c.grid.d_max, c.grid.bins_per_decade)),
      phase_(c.base.engine.populations.front().phase),
      density_(c.base.engine.populations.front().density),
      coag_(coagulation(grid_, c.base.engine)),
      stepper_(coag_, grid_.x, c.grid.tolerance),
      initial_(project(grid_, c.base.engine.populations)),
      n_(initial_.n) {}

void SectionalSolver::advance_to(double t) {
  if (t > t_) stepper_.advance(n_, t_, t);
  t_ = std::max(t_, t);
}

double SectionalSolver::number() const {
  double s = 0.0;
  for (double v : n_) s += v;
  return s;
}

double SectionalSolver::volume() const {
  double s = 0.0;
  for (std::size_t i = 0; i < n_.size(); ++i) s += n_[i] * grid_.x[i];
  return s;
}

}  // namespace agglo::sectional
