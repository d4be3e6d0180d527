// Structure checks and file input (structure/validate.hpp, csv_input.hpp), and the observables.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "agglo/structure/csv_input.hpp"
#include "agglo/structure/validate.hpp"

namespace agglo::structure {
namespace {

Aggregate from_csv(const std::string& text) {
  std::istringstream in(text);
  return read_aggregate_csv(in, "test.csv", "file");
}

TEST(Validate, TouchingChainPassesWithItsCoordination) {
  const Aggregate a = from_csv("x,y,z,radius,charge\n0,0,0,1,1e-15\n2,0,0,1,0\n2,2,0,1,-1e-15\n");
  const Contacts c = validate_structure(a, "file");
  EXPECT_EQ(c.pairs.size(), 2u);
  EXPECT_EQ(c.coordination, (std::vector<int>{1, 2, 1}));
  EXPECT_EQ(coordination_histogram(c.coordination), (std::vector<int>{0, 2, 1}));
  ASSERT_EQ(a.charge.size(), 3u);
  EXPECT_EQ(a.charge[2], -1e-15);
}

TEST(Validate, OverlapIsRejectedNamingThePrimaries) {
  const Aggregate a = from_csv("x,y,z,radius\n0,0,0,1\n1.9,0,0,1\n");
  try {
    (void)validate_structure(a, "file");
    FAIL();
  } catch (const BuildError& e) {
    EXPECT_EQ(e.key, "file");
    EXPECT_NE(std::string(e.what()).find("primaries 0 and 1 overlap"), std::string::npos) << e.what();
  }
}

TEST(Validate, ContactErrorAboveToleranceIsAGap) {
  // 2e-6 r apart: neither a contact nor an overlap, so the pair is disconnected.
  const Aggregate a = from_csv("x,y,z,radius\n0,0,0,1\n2.000002,0,0,1\n");
  EXPECT_THROW((void)validate_structure(a, "file"), BuildError);
  const Aggregate b = from_csv("x,y,z,radius\n0,0,0,1\n2.0000005,0,0,1\n");
  EXPECT_EQ(validate_structure(b, "file").pairs.size(), 1u);
}

TEST(Validate, DisconnectedIsRejected) {
  const Aggregate a = from_csv("x,y,z,radius\n0,0,0,1\n2,0,0,1\n10,0,0,1\n12,0,0,1\n");
  try {
    (void)validate_structure(a, "file");
    FAIL();
  } catch (const BuildError& e) {
    EXPECT_NE(std::string(e.what()).find("2 disconnected groups"), std::string::npos) << e.what();
  }
}

TEST(Validate, BadCsvNamesLineAndColumn) {
  EXPECT_THROW((void)from_csv("x,y,radius\n0,0,1\n"), BuildError);
  try {
    (void)from_csv("x,y,z,radius\n0,0,0,1\n0,abc,0,1\n");
    FAIL();
  } catch (const BuildError& e) {
    EXPECT_NE(std::string(e.what()).find("test.csv line 3"), std::string::npos) << e.what();
  }
}

TEST(Observables, RadiiOfGyrationOfADimer) {
  // Two touching unit spheres: point-mass R_g = 1; solid spheres: sqrt(1 + 3/5).
  const Aggregate a = from_csv("x,y,z,radius\n-1,0,0,1\n1,0,0,1\n");
  EXPECT_DOUBLE_EQ(rg_point_mass(a), 1.0);
  EXPECT_DOUBLE_EQ(rg_spheres(a), std::sqrt(1.6));
}

TEST(Observables, FitRecoversAPowerLaw) {
  std::vector<double> n, rg;
  for (double N : {10.0, 40.0, 160.0}) {
    n.push_back(N);
    rg.push_back(std::pow(N / 1.7, 1.0 / 2.1));
  }
  const FractalFit f = fit_fractal(n, rg);
  EXPECT_NEAR(f.fractal_dimension, 2.1, 1e-12);
  EXPECT_NEAR(f.fractal_prefactor, 1.7, 1e-12);
}

}  // namespace
}  // namespace agglo::structure
