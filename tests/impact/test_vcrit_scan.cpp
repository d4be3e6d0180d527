// vcrit.order = "top_down" against the full order (impact/vcrit.hpp): on synthetic outcome maps (a
// threshold, breaking islands below it, intact islands above it) both searches give the same v_crit,
// bracket and rounds; the top-down search runs a subset of the full search's runs that holds all of those
// at or above the bracket's lower end, each batch highest speed first. Negative control: a batch that ignores the stop rule and
// returns every run still gives the same bracket (the rule only saves runs), while a top-down search that
// stopped at the first *broken* speed would not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "agglo/impact/vcrit.hpp"

using namespace agglo::impact;

namespace {

using Map = std::function<bool(double)>;  // speed -> broken

struct Counting {
  Map broken;
  bool honour_stop = true;
  long runs = 0;
  bool descending = true;  // every batch arrived highest speed first
  std::vector<ImpactOutcome> operator()(const std::vector<double>& speeds, const StopRule& stop) {
    descending = descending && std::is_sorted(speeds.begin(), speeds.end(), std::greater<>());
    std::vector<ImpactOutcome> out;
    for (double v : speeds) {
      ImpactOutcome o;
      o.speed = v;
      o.contact = true;
      o.broken = broken(v);
      out.push_back(o);
      ++runs;
      if (honour_stop && stop && stop(o)) break;
    }
    return out;
  }
};

VcritSpec spec_with(int per_round, double tolerance) {
  VcritSpec s;
  s.v_min = 0.02;
  s.v_max = 0.6;
  s.scan_points = 12;
  s.tolerance = tolerance;
  s.points_per_round = per_round;
  return s;
}

VcritResult search(VcritSpec spec, bool top_down, Counting& batch) {
  spec.top_down = top_down;
  return find_vcrit(spec, std::ref(batch));
}

// Threshold v_star; pattern 1 adds a breaking island below it, pattern 2 an intact island above it.
Map outcome_map(double v_star, int pattern) {
  return [v_star, pattern](double v) {
    if (pattern == 1 && v > 0.5 * v_star && v < 0.6 * v_star) return true;
    if (pattern == 2 && v > v_star + 0.01 && v < v_star + 0.03) return false;
    return v >= v_star;
  };
}

}  // namespace

TEST(VcritOrder, TopDownKeepsTheBracketAndSkipsOnlyRunsBelowIt) {
  int searches = 0, fewer = 0;
  for (int pattern = 0; pattern < 3; ++pattern)
    for (int per_round = 1; per_round <= 3; ++per_round)
      for (int k = 0; k < 80; ++k) {
        const double v_star = 0.07 + 0.45 * (k + 0.37) / 80.0;
        const VcritSpec spec = spec_with(per_round, 5e-4);
        Counting full{outcome_map(v_star, pattern)}, top{outcome_map(v_star, pattern)};
        const VcritResult a = search(spec, false, full);
        const VcritResult b = search(spec, true, top);
        ++searches;
        ASSERT_EQ(a.v_crit, b.v_crit) << "v* " << v_star << " pattern " << pattern;
        EXPECT_EQ(a.lo, b.lo);
        EXPECT_EQ(a.hi, b.hi);
        EXPECT_EQ(a.rounds, b.rounds);
        EXPECT_TRUE(top.descending);
        // Every top-down run is a run of the full search, and every full run at or above the bracket's
        // lower end is a top-down run (below it, top-down keeps only earlier rounds' lower ends).
        std::vector<double> sa, sb;
        for (const auto& r : a.runs) sa.push_back(r.speed);
        for (const auto& r : b.runs) sb.push_back(r.speed);
        EXPECT_TRUE(std::includes(sa.begin(), sa.end(), sb.begin(), sb.end()));
        for (const auto& r : a.runs) {
          EXPECT_TRUE(r.speed < a.lo || std::binary_search(sb.begin(), sb.end(), r.speed)) << r.speed;
        }
        for (const auto& r : b.runs) {
          EXPECT_TRUE(r.speed >= b.lo || !r.broken);
        }
        EXPECT_EQ(top.runs, static_cast<long>(b.runs.size()));
        EXPECT_LE(top.runs, full.runs);
        fewer += top.runs < full.runs;
      }
  EXPECT_EQ(searches, 720);
  EXPECT_GT(fewer, 600);  // the scan alone runs ~3 speeds below v_star for most thresholds
}

TEST(VcritOrder, NonMonotonicWarningsOnlyFromRunsThatRan) {
  // Pattern 1: the island below v_star breaks; the full scan sees it, the top-down scan never runs it.
  const Map m = outcome_map(0.4, 1);
  const VcritSpec spec = spec_with(2, 5e-4);
  Counting full{m}, top{m};
  const VcritResult a = search(spec, false, full);
  const VcritResult b = search(spec, true, top);
  EXPECT_EQ(a.v_crit, b.v_crit);
  auto non_monotonic = [](const VcritResult& r) {
    return std::count_if(r.warnings.begin(), r.warnings.end(),
                         [](const std::string& w) { return w.find("non-monotonic") != std::string::npos; });
  };
  EXPECT_GT(non_monotonic(a), 0);
  EXPECT_EQ(non_monotonic(b), 0);
}

TEST(VcritOrder, StopRuleOnlySavesRuns) {
  // A batch may run every speed and return them all: the bracket is the same (negative control for the
  // rule's role), and a wrong rule (stopping at the first broken speed from the top) changes the bracket.
  const Map m = outcome_map(0.2345, 2);
  const VcritSpec spec = spec_with(2, 5e-4);
  Counting honour{m}, ignore{m};
  ignore.honour_stop = false;
  const VcritResult a = search(spec, true, honour);
  const VcritResult b = search(spec, true, ignore);
  EXPECT_EQ(a.lo, b.lo);
  EXPECT_EQ(a.hi, b.hi);
  EXPECT_LT(honour.runs, ignore.runs);

  VcritSpec top = spec;
  top.top_down = true;
  Counting wrong{m};
  auto wrong_rule = [&](const std::vector<double>& speeds, const StopRule&) {
    return wrong(speeds, [](const ImpactOutcome& o) { return o.broken; });  // stops at the first break
  };
  EXPECT_THROW((void)find_vcrit(top, wrong_rule), std::exception);  // never sees a non-break: no bracket
}
