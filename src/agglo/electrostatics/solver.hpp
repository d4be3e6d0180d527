#pragma once
// Electrostatics of charged dielectric spheres: one interface, several solvers (docs/model.md Part B).
//
// Input: sphere centres [m], radii [m], free charges q [C] (uniform sigma_f = q/(4 pi r^2)),
// relative permittivities kappa_p, the medium permittivity kappa_0 and an applied field [V/m].
// Output: force [N] and torque [N m] on each sphere (about its centre), the energy
// U = 1/2 \int phi sigma_f dS [J] (docs/model.md §B.1), and solver statistics.
//
// Solvers are selected by name through make_solver(); the names are those of registry.hpp.
#include <array>
#include <compare>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/core/vec3.hpp"

namespace agglo::es {

struct Sphere {
  Vec3 center;              // [m]
  double radius = 0.0;      // [m], the electrostatic radius (after any min-gap shrinking)
  double charge = 0.0;      // free charge [C]
  double permittivity = 1;  // relative permittivity kappa_p (> 0)
};

struct Problem {
  std::vector<Sphere> spheres;
  double medium_permittivity = 1.0;  // kappa_0
  Vec3 external_field;               // [V/m]
};

struct SolverStats {
  int iterations = 0;        // GMRES iterations (0 for direct/closed-form solvers)
  double residual = 0.0;     // final relative residual
  double seconds = 0.0;      // wall time of the solve
  int degree = 0;            // spectral: expansion degree L used; bem: patches per sphere
  nlohmann::json extra;      // solver specific
};

struct Solution {
  std::vector<Vec3> force;   // [N]
  std::vector<Vec3> torque;  // [N m], about each sphere's centre
  double energy = 0.0;       // [J]
  SolverStats stats;
};

// Surface sample for output (.vtu): position, outward normal, patch area, charge densities [C/m^2].
struct SurfaceSample {
  Vec3 position, normal;
  double area = 0.0;
  double sigma_free = 0.0, sigma_bound = 0.0;
  int body = 0;
};

// What a solver keeps from one solve for the next (its warm start), as opaque numbers for
// checkpoints: restoring it into a solver of the same options makes the next solve bitwise identical
// to the one of the solver it was taken from.
struct WarmStart {
  std::vector<long long> ints;
  std::vector<double> values;
};

class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string name() const = 0;
  // Solve; implementations may keep state to warm-start the next call (same number of spheres).
  virtual Solution solve(const Problem& p) = 0;
  // Surface charge of the last solve (for output). Solvers without a surface return point samples.
  virtual std::vector<SurfaceSample> surface() const = 0;
  // Optional triangulation of surface(): vertex triples indexing the samples (counter-clockwise
  // seen from outside). Empty when the samples are a point cloud.
  virtual std::vector<std::array<int, 3>> surface_triangles() const { return {}; }
  // The warm start of the next solve (none by default: a solver without one is stateless).
  virtual WarmStart warm_start() const { return {}; }
  virtual void set_warm_start(const WarmStart&) {}
};

// Every field is a solver setting. The defaulted comparison covers all fields, present and future
// (caches of solver results, e.g. impact/pair_table.hpp, key on the whole struct through it).
// The solver a case gets when it names none (electrostatics.solver); the spectral solver's name.
inline constexpr std::string_view kDefaultSolver = "spectral";
// Far field of the spectral product (electrostatics.far_field; spectral/far_field.hpp): every pair
// re-expanded directly ("dense", the default and the reference twin) or well-separated pairs through an
// octree of sphere expansions ("fmm"). The key's allowed values are these names.
inline constexpr std::array<std::string_view, 2> kFarFieldNames{"dense", "fmm"};
// Right preconditioner P of the spectral solver's GMRES (A P^-1 u = b, x = P^-1 u: the residual is the
// true one; docs/electrostatics.md, "Sixth session"): "none"; "coarse", the two-level block of the
// low degrees (the system restricted to degrees <= 8, solved by an inner GMRES, identity above);
// "pair", block Jacobi over a matching of the close pairs (each pair's two-sphere system solved by an
// inner GMRES); "contact", the system of all close pairs at once (the contact network, inner GMRES):
// measuring tools that cost more than they save. "contact_low": two Neumann steps of the contact system
// truncated to degrees <= 20 and pair-frame orders <= 2, P^-1 = I - X + X^2 with X = gamma M_low (cheap). The case key
// electrostatics.preconditioner (keys.hpp) takes these names.
inline constexpr std::array<std::string_view, 5> kPreconditionerNames{"none", "coarse", "pair", "contact",
                                                                      "contact_low"};

// Neumann steps of the contact_low preconditioner unless a case sets them (spectral_solver.cpp: why two).
inline constexpr int kContactLowSteps = 2;

struct SolverOptions {
  std::string solver{kDefaultSolver};  // a registered name (registry.hpp)
  // spectral
  int max_degree = 0;               // 0 = choose L from the smallest gap for `target_accuracy`
  double target_accuracy = 1e-4;    // relative force accuracy used to pick L
  int max_degree_limit = 80;        // hard cap on automatically chosen L
  std::string far_field{kFarFieldNames[0]};  // a name of kFarFieldNames
  std::string preconditioner{kPreconditionerNames[0]};  // a name of kPreconditionerNames
  // preconditioner = "contact_low": its Neumann steps (case key electrostatics.preconditioner_steps; the
  // benchmark's acceptance row at kappa_p = 15 takes 3: docs/electrostatics.md, "Eighth session").
  int contact_low_steps = kContactLowSteps;
  // bem
  int patches_per_sphere = 2000;
  double tolerance = 1e-6;          // GMRES relative residual
  int max_iterations = 200;
  std::string matvec = "fmm";       // "fmm" | "direct"
  int fmm_order = 0;                // 0 = chosen from tolerance (1-2 digits tighter than GMRES)
  int fmm_leaf_size = 64;

  friend auto operator<=>(const SolverOptions&, const SolverOptions&) = default;
};

// The solver opt.solver names (registry.cpp); throws agglo::ConfigError for an unknown name.
std::unique_ptr<Solver> make_solver(const SolverOptions& opt);

}  // namespace agglo::es
