// One validation of the solver input (validate_spheres.hpp), used by every solver: each violation
// gives InvalidSpheres with its reason and sphere indices, from the function and from each solver.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "agglo/electrostatics/solver.hpp"
#include "agglo/electrostatics/validate_spheres.hpp"

using namespace agglo;
using namespace agglo::es;

namespace {

constexpr double kSphereRadius = 10e-6;

Problem good() {
  Problem p;
  p.spheres = {Sphere{{0, 0, 0}, kSphereRadius, 1e-14, 2.5},
               Sphere{{2.2 * kSphereRadius, 0, 0}, kSphereRadius, -1e-14, 2.5},
               Sphere{{0, 2.5 * kSphereRadius, 0}, kSphereRadius, 0.0, 2.5}};
  return p;
}

struct Case {
  std::string name;
  std::function<void(Problem&)> spoil;
  InvalidSpheres::Reason reason;
  int first, second;
};

std::vector<Case> cases() {
  using Rs = InvalidSpheres::Reason;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  return {
      {"medium 0", [](Problem& p) { p.medium_permittivity = 0.0; }, Rs::medium_permittivity, -1, -1},
      {"medium inf", [inf](Problem& p) { p.medium_permittivity = inf; }, Rs::medium_permittivity, -1, -1},
      {"field nan", [nan](Problem& p) { p.external_field.y = nan; }, Rs::external_field, -1, -1},
      {"radius 0", [](Problem& p) { p.spheres[1].radius = 0.0; }, Rs::radius, 1, -1},
      {"radius < 0", [](Problem& p) { p.spheres[2].radius = -kSphereRadius; }, Rs::radius, 2, -1},
      {"radius nan", [nan](Problem& p) { p.spheres[0].radius = nan; }, Rs::radius, 0, -1},
      {"kappa 0", [](Problem& p) { p.spheres[2].permittivity = 0.0; }, Rs::permittivity, 2, -1},
      {"kappa < 0", [](Problem& p) { p.spheres[0].permittivity = -2.0; }, Rs::permittivity, 0, -1},
      {"kappa inf", [inf](Problem& p) { p.spheres[1].permittivity = inf; }, Rs::permittivity, 1, -1},
      {"centre nan", [nan](Problem& p) { p.spheres[1].center.z = nan; }, Rs::non_finite, 1, -1},
      {"charge inf", [inf](Problem& p) { p.spheres[2].charge = inf; }, Rs::non_finite, 2, -1},
      {"overlap", [](Problem& p) { p.spheres[2].center = {0.5 * kSphereRadius, 1.5 * kSphereRadius, 0}; }, Rs::overlap, 0, 2},
      {"touch", [](Problem& p) { p.spheres[1].center = {2 * kSphereRadius, 0, 0}; }, Rs::overlap, 0, 1},
  };
}

void expect_invalid(const std::function<void()>& f, const Case& c, const std::string& who) {
  try {
    f();
    ADD_FAILURE() << who << ": " << c.name << " accepted";
  } catch (const InvalidSpheres& e) {
    EXPECT_EQ(e.reason, c.reason) << who << ": " << c.name;
    EXPECT_EQ(e.first, c.first) << who << ": " << c.name;
    EXPECT_EQ(e.second, c.second) << who << ": " << c.name;
    EXPECT_EQ(std::string(e.what()), "electrostatics: " + e.detail);
    // physics only: no configuration key (they all contain '_') in the message
    EXPECT_EQ(e.detail.find('_'), std::string::npos) << e.detail;
  }
}

}  // namespace

TEST(ValidateSpheres, AcceptsSeparatedSpheres) {
  EXPECT_NO_THROW(validate_spheres(good()));
  EXPECT_NO_THROW(validate_spheres(Problem{}));
}

TEST(ValidateSpheres, EachViolationHasItsReasonAndSpheres) {
  for (const auto& c : cases()) {
    Problem p = good();
    c.spoil(p);
    expect_invalid([&] { validate_spheres(p); }, c, "validate_spheres");
  }
}

TEST(ValidateSpheres, IsANumericalError) {
  Problem p = good();
  p.spheres[0].radius = 0.0;
  EXPECT_THROW(validate_spheres(p), NumericalError);
}

TEST(ValidateSpheres, EverySolverRejectsTheSameInputs) {
  for (const std::string name : {"coulomb", "spectral", "bem"}) {
    SolverOptions o;
    o.solver = name;
    o.patches_per_sphere = 100;
    o.matvec = "direct";
    auto solver = make_solver(o);
    for (const auto& c : cases()) {
      Problem p = good();
      c.spoil(p);
      expect_invalid([&] { solver->solve(p); }, c, name);
    }
  }
}
