// The vcrit bisection always ends: with a tolerance below the spacing of doubles (which the case
// parser refuses, docs/dem.md "Limits and checks") it stops once its midpoints no longer move.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "agglo/impact/vcrit.hpp"

using namespace agglo::impact;

TEST(VcritBisection, StopsWhenMidpointsDoNotMove) {
  VcritSpec spec;
  spec.v_min = 0.02;
  spec.v_max = 0.6;
  spec.scan_points = 12;
  spec.tolerance = 1e-30;  // unreachable: the bracket cannot shrink below ~1e-17 m/s
  spec.points_per_round = 2;
  const double v_star = 0.2345678901234567;
  long calls = 0;
  auto batch = [&](const std::vector<double>& speeds, const StopRule&) {
    std::vector<ImpactOutcome> out;
    for (double v : speeds) {
      ImpactOutcome o;
      o.speed = v;
      o.contact = true;
      o.broken = v >= v_star;
      out.push_back(o);
    }
    if (++calls > 1000) throw std::runtime_error("bisection does not end");
    return out;
  };
  const VcritResult res = find_vcrit(spec, batch);
  EXPECT_LT(res.rounds, 200);
  EXPECT_GE(res.v_crit, v_star);
  EXPECT_LE(res.v_crit - v_star, 1e-15);
  ASSERT_FALSE(res.warnings.empty());
  EXPECT_NE(res.warnings.back().find("cannot shrink"), std::string::npos);
}
