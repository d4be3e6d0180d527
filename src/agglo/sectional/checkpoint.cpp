#include "agglo/sectional/checkpoint.hpp"

#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo::sectional {

static_assert(sizeof(StepStats) == 4 * 8, "StepStats changed: check it has no padding");

class SolverCheckpoint {
 public:
  static void save(const SectionalSolver& s, io::CheckpointWriter& w) {
    w.f64(s.t_);
    w.pod_vector(s.n_);
    w.f64(s.stepper_.h_);
    w.pod(s.stepper_.stats_);
  }

  static void load(SectionalSolver& s, io::CheckpointReader& r) {
    s.t_ = r.f64();
    auto n = r.pod_vector<double>();
    if (n.size() != s.n_.size())
      throw ConfigError(fmt::format("checkpoint {}: pivot count {} does not match this case's {}", r.file(), n.size(),
                                    s.n_.size()));
    s.n_ = std::move(n);
    s.stepper_.h_ = r.f64();
    s.stepper_.stats_ = r.pod<StepStats>();
  }
};

void save_solver(const SectionalSolver& s, io::CheckpointWriter& w) { SolverCheckpoint::save(s, w); }
void load_solver(SectionalSolver& s, io::CheckpointReader& r) { SolverCheckpoint::load(s, r); }

}  // namespace agglo::sectional
