#include "isolated_spheres_solver.hpp"

#include "agglo/core/constants.hpp"

namespace agglo::es {

namespace {

class IsolatedSpheresSolver final : public Solver {
 public:
  std::string name() const override { return std::string(kIsolatedSolver); }

  Solution solve(const Problem& p) override {
    using constants::eps0, constants::pi;
    last_ = p;
    Solution s;
    for (const Sphere& b : p.spheres) {
      s.force.push_back(b.charge * p.external_field);
      s.torque.push_back({});
      s.energy += b.charge * b.charge / (8.0 * pi * eps0 * p.medium_permittivity * b.radius);
      s.energy -= 0.5 * b.charge * dot(p.external_field, b.center);
    }
    return s;
  }

  std::vector<SurfaceSample> surface() const override {
    std::vector<SurfaceSample> out;
    for (std::size_t i = 0; i < last_.spheres.size(); ++i) {
      SurfaceSample s;
      s.position = last_.spheres[i].center;
      s.body = static_cast<int>(i);
      out.push_back(s);
    }
    return out;
  }

 private:
  Problem last_;
};

}  // namespace

std::unique_ptr<Solver> make_isolated_spheres_solver(const SolverOptions&) {
  return std::make_unique<IsolatedSpheresSolver>();
}

}  // namespace agglo::es
