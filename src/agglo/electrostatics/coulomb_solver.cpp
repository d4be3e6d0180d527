// Point-charge solver (docs/model.md §B.2 item 1). See coulomb_solver.hpp.
#include "agglo/electrostatics/coulomb_solver.hpp"

#include <chrono>
#include <cmath>

#include "agglo/core/constants.hpp"
#include "agglo/electrostatics/sphere_mesh.hpp"
#include "agglo/electrostatics/validate_spheres.hpp"

namespace agglo::es {

using constants::eps0;
using constants::pi;

double coulomb_forces(const Problem& p, std::vector<Vec3>& force, std::vector<Vec3>& torque) {
  const int N = static_cast<int>(p.spheres.size());
  const double k0 = p.medium_permittivity;
  force.assign(N, Vec3{});
  torque.assign(N, Vec3{});
  const double kc = 1.0 / (4 * pi * eps0 * k0);
  double U = 0.0;
  for (int i = 0; i < N; ++i) {
    const auto& a = p.spheres[i];
    // self energy of the uniform shell: q^2 / (8 pi eps0 kappa0 r); applied potential -E.x
    U += 0.5 * kc * a.charge * a.charge / a.radius - 0.5 * a.charge * dot(p.external_field, a.center);
    force[i] += p.external_field * a.charge;
    for (int k = i + 1; k < N; ++k) {
      const auto& b = p.spheres[k];
      Vec3 d = a.center - b.center;
      double r = norm(d);
      Vec3 f = d * (kc * a.charge * b.charge / (r * r * r));
      force[i] += f;
      force[k] -= f;
      U += kc * a.charge * b.charge / r;
    }
  }
  return U;
}

namespace {

class CoulombSolver final : public Solver {
 public:
  explicit CoulombSolver(const SolverOptions& opt) : opt_(opt) {}
  std::string name() const override { return std::string(kCoulombSolver); }

  Solution solve(const Problem& p) override {
    auto t0 = std::chrono::steady_clock::now();
    validate_spheres(p);
    Solution sol;
    sol.energy = coulomb_forces(p, sol.force, sol.torque);
    last_ = p;
    sol.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return sol;
  }

  // Uniform free charge; the bound charge of a point-charge model is taken as the part that makes
  // the net charge q / kappa0 (uniform), i.e. sigma_b = sigma_f (1/kappa0 - 1).
  std::vector<SurfaceSample> surface() const override {
    std::vector<SurfaceSample> out;
    auto mesh = icosphere(icosphere_level_for(std::min(opt_.patches_per_sphere, 642)));
    for (std::size_t i = 0; i < last_.spheres.size(); ++i) {
      const auto& s = last_.spheres[i];
      double sf = s.charge / (4 * pi * s.radius * s.radius);
      for (const auto& n : mesh.vertices) {
        SurfaceSample ss;
        ss.position = s.center + n * s.radius;
        ss.normal = n;
        ss.area = 4 * pi * s.radius * s.radius / mesh.vertices.size();
        ss.sigma_free = sf;
        ss.sigma_bound = sf * (1.0 / last_.medium_permittivity - 1.0);
        ss.body = static_cast<int>(i);
        out.push_back(ss);
      }
    }
    return out;
  }

  std::vector<std::array<int, 3>> surface_triangles() const override {
    std::vector<std::array<int, 3>> tri;
    auto mesh = icosphere(icosphere_level_for(std::min(opt_.patches_per_sphere, 642)));
    const int nv = static_cast<int>(mesh.vertices.size());
    for (std::size_t i = 0; i < last_.spheres.size(); ++i)
      for (const auto& t : mesh.triangles)
        tri.push_back({t[0] + int(i) * nv, t[1] + int(i) * nv, t[2] + int(i) * nv});
    return tri;
  }

 private:
  SolverOptions opt_;
  Problem last_;
};

}  // namespace

std::unique_ptr<Solver> make_coulomb_solver(const SolverOptions& opt) { return std::make_unique<CoulombSolver>(opt); }

// O(N) memory, N^2 interactions (the registry's defaults); surface samples of an icosphere of at
// most 642 vertices per sphere.
SolverType coulomb_solver_type() {
  return {.name = kCoulombSolver,
          .make = &make_coulomb_solver,
          .samples_per_sphere = [](const SolverOptions& opt) {
            return static_cast<double>(icosphere_vertices_for(std::min(opt.patches_per_sphere, 642)));
          },
          .induced_charges = false};
}

}  // namespace agglo::es
