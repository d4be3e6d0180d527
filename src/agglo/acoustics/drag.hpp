#pragma once
// Particle motion in the sound field (docs/model.md §C.2; Zhao et al. 2023, eqs. 3-5):
//   m dv/dt = 3 pi mu_g d (u_g - v) C_I / C_c + (rho - rho_g) pi d^3 g / 6
// i.e. dv/dt = (u_g - v)/tau_e + a,  tau_e = tau / C_I,  a = -g (rho - rho_g)/rho e_z.
// d is the mobility diameter d_m of an aggregate (structure.hpp: tau = m C_c(d_m) / (3 pi mu_g d_m), C_I at
// Re = rho_g |u_g - v| d_m / mu_g; the weight term is m g (1 - rho_g/rho)); the volume-equivalent diameter
// of a compact sphere.
// Integrators over a step h:
//  - exact: C_I frozen over the step and x frozen in the wave phase; the linear ODE with
//    sinusoidal forcing is then solved in closed form (velocity and position), so h may be much
//    larger than tau (default). Where C_I - 1 > 1e-3 (droplets) C_I is taken at the mid-step
//    slip predicted with the start-of-step C_I (second order in h); elsewhere at the start.
//  - explicit: Zhao et al.'s explicit scheme (forward Euler for v, then x += h v_new); stable only
//    for h < 2 tau_e (the engine checks this).
//  - none: particles keep their positions and velocities (test kernels).
#include <cstddef>
#include <cstdint>

#include "agglo/acoustics/gas.hpp"
#include "agglo/acoustics/samples.hpp"
#include "agglo/acoustics/sound.hpp"

namespace agglo::acoustics {

enum class Integrator { exact, explicit_euler, none };

// Largest total cell count accepted (docs/acoustics.md, "Limits and checks"): cell indices are 32-bit
// and every cell holds statistics, so 1e8 cells (several GB) is the most a run can afford.
inline constexpr std::int64_t kMaxCells = 100000000;

struct Domain {
  double L[3] = {0, 0, 0};  // periodic box lengths [m]
  int cells[3] = {1, 1, 1};
  double volume() const { return L[0] * L[1] * L[2]; }
  double cell_volume() const { return volume() / static_cast<double>(num_cells()); }
  // 64-bit product: parse_acoustic_case refuses more than kMaxCells (so int cell indices are safe).
  std::int64_t num_cells() const {
    return static_cast<std::int64_t>(cells[0]) * static_cast<std::int64_t>(cells[1]) * static_cast<std::int64_t>(cells[2]);
  }
};

struct Motion {
  Gas gas;
  Sound sound;
  Domain domain;
  Integrator integrator = Integrator::exact;
  bool inertia_correction = true;
  // Widest SIMD step advance_exact_pairs may use: 4 (AVX2 where the processor has it) or 2 (SSE2 only;
  // the tests check both against the reference).
  int max_lanes = 4;

  // Effective relaxation time tau/C_I of sample i for its current slip at time t.
  double effective_tau(const SampleSet& p, std::size_t i, double t) const;
  // Steady periodic response to the wave plus terminal settling velocity at time t (initial state).
  void set_steady_velocity(SampleSet& p, std::size_t i, double t) const;
  // Advance samples [begin, end) from t to t + h with the chosen integrator using `substeps`
  // sub-steps (explicit scheme) or one closed-form step (exact). Positions are wrapped.
  void advance(SampleSet& p, std::size_t begin, std::size_t end, double t, double h, int substeps) const;
  // Time trigonometry of an exact step from t over h: swt, cwt = sin, cos(omega t); swh, cwh =
  // sin, cos(omega h); swh2, cwh2 = sin, cos(omega h / 2).
  struct StepTrig {
    double swt, cwt, swh, cwh, swh2, cwh2;
    double inv_omega;  // 1 / omega
  };
  StepTrig trig(double t, double h) const;
  // Exact step of samples [begin, end), in stages over blocks of samples (instruction-level parallelism).
  void advance_exact_block(SampleSet& p, std::size_t begin, std::size_t end, const StepTrig& tr, double h) const;
  // The same step of sample i alone, written plainly (the tested reference of advance_exact_block).
  void advance_exact(SampleSet& p, std::size_t i, const StepTrig& tr, double h) const;
  // The same step four samples at a time in AVX2 lanes (where the processor has them), then two in
  // SSE2 lanes (drag_pairs.cpp, drag_lanes.inc; the step used by advance): the reference's operations
  // in the reference's order, so bit for bit advance_exact's results. Without sound or without C_I (not
  // the default) it is advance_exact_block.
  void advance_exact_pairs(SampleSet& p, std::size_t begin, std::size_t end, const StepTrig& tr, double h) const;
  void advance_explicit(SampleSet& p, std::size_t i, double t, double h) const;
  void wrap(SampleSet& p, std::size_t i) const;
};

}  // namespace agglo::acoustics
