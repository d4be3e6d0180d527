// Aggregate structure of DSMC samples (structure.hpp, docs/acoustics.md §1.8): the fractal collision radius
// against its law, the compact limit D_f = 3, k_f = 1, kernels and drag through the collision and mobility
// radii against formulas written here, and primary count and mass in merges and breakage.
#include <cmath>
#include <numeric>
#include <string>

#include <gtest/gtest.h>

#include "agglo/acoustics/diagnostics.hpp"
#include "agglo/acoustics/fragments.hpp"
#include "agglo/acoustics/kernels.hpp"
#include "agglo/acoustics/merge.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "helpers.hpp"

using namespace agglo::acoustics;
using agglo::constants::k_B;
using agglo::constants::pi;

namespace {

StructureLaw fractal_law(double rp, double df, double kf, MobilityRule mob = MobilityRule::collision) {
  StructureLaw l;
  l.fractal = true;
  l.primary_radius = rp;
  l.fractal_dimension = df;
  l.fractal_prefactor = kf;
  l.mobility = mob;
  return l;
}

struct Air {
  Gas gas = Gas::air(298.15, 101325.0, true);
  Sound snd = Sound::make(gas, true, 147.0, 1400.0);
};

// Solid sample of n primaries of radius rp [m], density 2500 kg/m^3, weight w, velocity vx.
std::size_t add_aggregate(SampleSet& p, const Air& a, double n, double rp, double w, double vx, int pop = 0) {
  const double v = n * 4.0 / 3.0 * pi * rp * rp * rp;
  const std::size_t i = p.add(0.001, 0.001, 0.001, v, 0.0, 2500.0 * v, w, pop, a.gas, a.snd);
  p.set_primaries(i, rp, a.gas, a.snd);
  p.vx[i] = vx;
  return i;
}

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// R_c of the law, written as exp(ln(n / k_f) / D_f) (structure.cpp uses pow).
double law_radius(double n, double rp, double df, double kf) { return rp * std::exp(std::log(n / kf) / df); }

}  // namespace

TEST(Structure, CollisionRadiusFollowsTheFractalLaw) {
  const double rp = 20e-9, df = 1.8, kf = 1.3;
  const StructureLaw law = fractal_law(rp, df, kf);
  for (double n : {10.0, 64.0, 1000.0, 1e5}) {
    const double rv = rp * std::cbrt(n);
    EXPECT_LT(rel(collision_radius(law, n, rp, rv), law_radius(n, rp, df, kf)), 1e-13) << n;
    EXPECT_GT(collision_radius(law, n, rp, rv), rv) << n;  // an open aggregate is larger than its volume
  }
  // Few primaries with k_f > 1: the law gives less than r_v, so the sample is a compact sphere.
  EXPECT_LT(law_radius(1.0, rp, df, kf), rp);
  EXPECT_EQ(collision_radius(law, 1.0, rp, rp), rp);
  EXPECT_EQ(collision_radius(law, 0.4, rp, rp * std::cbrt(0.4)), rp * std::cbrt(0.4));
  // Sorensen's continuum mobility radius r_p n^0.46, and the "collision" rule R_m = R_c.
  const StructureLaw sor = fractal_law(rp, df, kf, MobilityRule::sorensen);
  EXPECT_LT(rel(mobility_radius(sor, 200.0, rp, rp * std::cbrt(200.0)), rp * std::exp(0.46 * std::log(200.0))), 1e-13);
  EXPECT_EQ(mobility_radius(law, 200.0, rp, rp * std::cbrt(200.0)), collision_radius(law, 200.0, rp, rp * std::cbrt(200.0)));
}

TEST(Structure, FractalPathWithDf3Kf1IsTheCompactPath) {
  // D_f = 3, k_f = 1: R_c = r_p n^(1/3) = r_v. A single primary of the sample's own radius, and 8 primaries
  // of half of it, give the compact sample's caches and kernels to rounding.
  const Air a;
  SampleSet compact, fractal;
  const double d = 1.3e-6, v = pi * d * d * d / 6.0;
  for (SampleSet* s : {&compact, &fractal}) {
    if (s == &fractal) s->structure_laws = {fractal_law(0.5 * d, 3.0, 1.0)};
    s->add(0.001, 0.001, 0.001, v, 0.0, 2500.0 * v, 3.0, 0, a.gas, a.snd);
    s->add(0.002, 0.001, 0.001, v / 8.0, 0.0, 2500.0 * v / 8.0, 5.0, 0, a.gas, a.snd);
    s->vx = {0.3, -0.2};
  }
  fractal.set_primaries(0, 0.5 * d, a.gas, a.snd);    // one primary of radius d/2
  fractal.set_primaries(1, 0.125 * d, a.gas, a.snd);  // the second sample (diameter d/2): 8 primaries of d/8
  EXPECT_NEAR(fractal.np[0], 1.0, 1e-12);
  EXPECT_NEAR(fractal.np[1], 8.0, 1e-12);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_LT(rel(fractal.d[i], compact.d[i]), 1e-14) << i;
    EXPECT_LT(rel(fractal.dm[i], compact.d[i]), 1e-14) << i;
    for (auto f : {&SampleSet::cc, &SampleSet::tau, &SampleSet::slip_l, &SampleSet::ccd, &SampleSet::dl})
      EXPECT_LT(rel((fractal.*f)[i], (compact.*f)[i]), 1e-13) << i;
    EXPECT_EQ(fractal.acc_z[i], compact.acc_z[i]);
  }
  const Kernel k(KernelSettings{}, a.gas, a.snd);  // the acoustic sum
  EXPECT_LT(rel(k.beta(fractal, 0, 1, 3e-6), k.beta(compact, 0, 1, 3e-6)), 1e-13);
}

TEST(Structure, OrthokineticKernelUsesTheCollisionDiameter) {
  // beta = (pi/4) (d_c,i + d_c,j)^2 |v_i - v_j| with d_c = 2 r_p (n / k_f)^(1/D_f).
  const Air a;
  const double rp = 25e-9, df = 1.8, kf = 1.3;
  SampleSet p;
  p.structure_laws = {fractal_law(rp, df, kf)};
  add_aggregate(p, a, 500.0, rp, 1.0, 0.4);
  add_aggregate(p, a, 40.0, rp, 1.0, -0.1);
  KernelSettings s;
  s.model = "orthokinetic";
  const Kernel k(s, a.gas, a.snd);
  const double dc = 2.0 * (law_radius(500.0, rp, df, kf) + law_radius(40.0, rp, df, kf));
  const double expect = 0.25 * pi * dc * dc * 0.5;
  EXPECT_LT(rel(k.beta(p, 0, 1, 0.0), expect), 1e-12);
  // Negative control: with the volume-equivalent diameters the kernel is several times smaller.
  const double dv = 2.0 * rp * (std::cbrt(500.0) + std::cbrt(40.0));
  EXPECT_GT(expect / (0.25 * pi * dv * dv * 0.5), 3.0);
}

TEST(Structure, BrownianKernelAndRelaxationTimeUseTheMobilityDiameter) {
  // Continuum Brownian with slip: beta = 2 pi (D_i + D_j)(d_c,i + d_c,j), D = k_B T C_c(d_m) / (3 pi mu d_m);
  // Sorensen's d_m = 2 r_p n^0.46; tau = m C_c(d_m) / (3 pi mu d_m).
  const Air a;
  const double rp = 15e-9, df = 1.8, kf = 1.3;
  SampleSet p;
  p.structure_laws = {fractal_law(rp, df, kf, MobilityRule::sorensen)};
  const double n[2] = {300.0, 20.0};
  for (double ni : n) add_aggregate(p, a, ni, rp, 1.0, 0.0);
  KernelSettings s;
  s.orthokinetic = s.acoustic_wake = s.radiation_pressure = false;  // the Brownian term alone
  const Kernel k(s, a.gas, a.snd);
  double D[2], dc[2];
  for (int i = 0; i < 2; ++i) {
    const double dm = 2.0 * rp * std::exp(0.46 * std::log(n[i]));
    const double cc = a.gas.slip_correction(dm);
    D[i] = k_B * a.gas.temperature * cc / (3.0 * pi * a.gas.viscosity * dm);
    dc[i] = 2.0 * law_radius(n[i], rp, df, kf);
    const double m = 2500.0 * n[i] * 4.0 / 3.0 * pi * rp * rp * rp;
    EXPECT_LT(rel(p.tau[i], m * cc / (3.0 * pi * a.gas.viscosity * dm)), 1e-12) << i;
    EXPECT_LT(rel(p.dm[i], dm), 1e-13) << i;
  }
  const double expect = 2.0 * pi * (D[0] + D[1]) * (dc[0] + dc[1]);
  EXPECT_LT(rel(k.beta(p, 0, 1, 0.0), expect), 1e-12);
  // Negative control: the same kernel of the compact spheres of the same volumes differs by > 20 %.
  double Dv = 0.0, dv = 0.0;
  for (double ni : n) {
    const double d = 2.0 * rp * std::cbrt(ni);
    Dv += k_B * a.gas.temperature * a.gas.slip_correction(d) / (3.0 * pi * a.gas.viscosity * d);
    dv += d;
  }
  EXPECT_GT(rel(2.0 * pi * Dv * dv, expect), 0.2);
}

TEST(Structure, MergeAddsPrimariesAndConservesVolume) {
  const Air a;
  for (auto [wi, wj] : {std::pair{4.0, 4.0}, {5.0, 5.0}, {7.0, 3.0}, {2.0, 9.0}}) {
    SampleSet p;
    p.structure_laws = {fractal_law(20e-9, 1.8, 1.3), fractal_law(40e-9, 2.2, 1.0)};
    add_aggregate(p, a, 50.0, 20e-9, wi, 0.3, 0);
    add_aggregate(p, a, 30.0, 40e-9, wj, -0.1, 1);
    const double n0 = p.w[0] * p.np[0] + p.w[1] * p.np[1];
    const double v0 = p.w[0] * p.vol_s[0] + p.w[1] * p.vol_s[1], m0 = p.w[0] * p.mass[0] + p.w[1] * p.mass[1];
    coalesce_weighted(p, 0, 1, a.gas, a.snd);
    EXPECT_LT(rel(p.w[0] * p.np[0] + p.w[1] * p.np[1], n0), 1e-14);
    EXPECT_LT(rel(p.w[0] * p.mass[0] + p.w[1] * p.mass[1], m0), 1e-14);
    EXPECT_LT(rel(p.w[0] * p.vol_s[0] + p.w[1] * p.vol_s[1], v0), 1e-14);
    const std::size_t m = wi >= wj ? 1 : 0;  // a merged sample
    EXPECT_EQ(p.np[m], 80.0);
    // Cube-mean primary radius: n_p (4/3) pi r_p^3 is the merged solid volume.
    EXPECT_LT(rel(p.np[m] * 4.0 / 3.0 * pi * std::pow(p.rp[m], 3), p.vol_s[m]), 1e-13);
    // Population of the partner of larger volume (30 x 8 > 50 primaries): its law sets the collision radius.
    EXPECT_EQ(p.pop[m], 1);
    EXPECT_LT(rel(p.d[m], 2.0 * law_radius(80.0, p.rp[m], 2.2, 1.0)), 1e-13);
  }
  // Same primary radius: the counts add exactly and the radius is kept.
  SampleSet q;
  q.structure_laws = {fractal_law(20e-9, 1.8, 1.3)};
  add_aggregate(q, a, 16.0, 20e-9, 2.0, 0.0);
  add_aggregate(q, a, 48.0, 20e-9, 2.0, 0.0);
  coalesce_weighted(q, 0, 1, a.gas, a.snd);
  EXPECT_NEAR(q.np[0], 64.0, 1e-12);
  EXPECT_EQ(q.rp[0], 20e-9);
}

TEST(Structure, BreakageGivesFragmentsPrimariesByMass) {
  const Air a;
  FragmentStats f;
  f.number = 5.0;
  f.largest = 0.4;
  for (auto [wi, wj] : {std::pair{6.0, 6.0}, {9.0, 4.0}, {3.0, 8.0}}) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      SampleSet p;
      p.structure_laws = {fractal_law(20e-9, 1.8, 1.3)};
      add_aggregate(p, a, 64.0, 20e-9, wi, 0.5);
      add_aggregate(p, a, 32.0, 20e-9, wj, -0.5);
      const double W = std::min(wi, wj);
      const double n_pairs = W * 96.0, m_pairs = W * (p.mass[0] + p.mass[1]);
      const double n_rest = (wi - W) * 64.0 + (wj - W) * 32.0;  // the heavier sample's unbroken part
      const double m_rest = (wi - W) * p.mass[0] + (wj - W) * p.mass[1];
      agglo::CounterRng rng(seed, 3, 4);
      break_weighted(p, 0, 1, f, rng, a.gas, a.snd);
      EXPECT_LT(rel(p.w[0] * p.np[0] + p.w[1] * p.np[1], n_pairs + n_rest), 1e-13);
      EXPECT_LT(rel(p.w[0] * p.mass[0] + p.w[1] * p.mass[1], m_pairs + m_rest), 1e-13);
      for (std::size_t i = 0; i < 2; ++i)  // n_p = V_s / v_p in every sample (primaries by mass)
        EXPECT_LT(rel(p.np[i] * 4.0 / 3.0 * pi * std::pow(p.rp[i], 3), p.vol_s[i]), 1e-13);
    }
  }
}

namespace {
// Constant kernel, no motion: a fractal population and droplets coalescing in one cell.
std::string fractal_box(const std::string& extra_population, const std::string& extra = "") {
  return "seed = 3\n" + std::string(test::kCoagulationBox) +
         test::constant_kernel_steps("2e-3", "initial_velocity = \"rest\"\n") +
         "[outcomes]\nalways_coalesce = true\n" + test::soot_population(400, "2e-8") + R"(fractal_dimension = 1.8
fractal_prefactor = 1.3
)" + extra_population + extra;
}
}  // namespace

TEST(Structure, EngineConservesPrimariesAndKeepsDropletsCompact) {
  Engine e = test::make_engine(fractal_box(R"(mobility_radius = "sorensen"
[[population]]
name = "drops"
phase = "liquid"
distribution = "monodisperse"
diameter = 1e-6
number_concentration = 2e11
samples = 100
)"));
  const SampleSet& p = e.particles();
  ASSERT_TRUE(p.structured());
  auto totals = [&] {
    double n = 0.0, m = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      n += p.w[i] * p.np[i];
      m += p.w[i] * p.mass[i];
    }
    return std::pair{n, m};
  };
  const auto [n0, m0] = totals();
  std::size_t aggregates = 0;
  for (std::size_t i = 0; i < p.size(); ++i) aggregates += p.d[i] > p.volume_diameter(i) * (1.0 + 1e-9) ? 1 : 0;
  EXPECT_GT(aggregates, 100u);  // most soot samples are larger than their volume
  const double N0 = test::total_number(p);
  for (int s = 0; s < 20; ++s) e.step();
  EXPECT_LT(test::total_number(p), 0.95 * N0);  // collisions happened
  const auto [n1, m1] = totals();
  EXPECT_LT(rel(n1, n0), 1e-12);
  EXPECT_LT(rel(m1, m0), 1e-12);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.w[i] <= 0.0) continue;
    if (p.phase(i) != Phase::solid) {  // droplets and wetted aggregates are compact spheres
      EXPECT_EQ(p.d[i], p.volume_diameter(i)) << i;
      EXPECT_EQ(p.dm[i], p.d[i]) << i;
    } else {
      EXPECT_GE(p.d[i], p.volume_diameter(i)) << i;
    }
  }
}

TEST(Structure, CaseKeysAreCheckedAndCompactKernelsRefused) {
  // Fractal keys without structure = "fractal", a fractal droplet population, and a compact-sphere kernel.
  const std::string compact_with_keys = std::string(test::kCoagulationBox) + R"(
[time]
end = 1e-4
collision_dt = 1e-4
[[population]]
name = "a"
phase = "solid"
distribution = "monodisperse"
diameter = 1e-6
number_concentration = 1e10
samples = 10
fractal_dimension = 1.8
)";
  EXPECT_THROW(test::parse_case(compact_with_keys), agglo::ConfigError);
  std::string droplets = fractal_box("");
  droplets.replace(droplets.find("phase = \"solid\""), 15, "phase = \"liquid\"");
  EXPECT_THROW(test::parse_case(droplets), agglo::ConfigError);
  std::string fuchs = fractal_box("");
  const std::string constant = "model = \"constant\"\nconstant_coefficient = 5e-10";
  fuchs.replace(fuchs.find(constant), constant.size(), "model = \"brownian_fuchs\"");
  try {
    test::parse_case(fuchs);
    FAIL() << "brownian_fuchs accepted with a fractal population";
  } catch (const agglo::ConfigError& err) {
    EXPECT_NE(std::string(err.what()).find("kernels.model"), std::string::npos) << err.what();
  }
  EXPECT_NO_THROW(test::parse_case(fractal_box("")));
}

TEST(Structure, AerodynamicPmCutUsesTheAggregatesSettling) {
  // An open aggregate of d_v = 3 um (2500 kg/m^3) settles as a much smaller sphere: with tau = m C_c(d_m) /
  // (3 pi mu d_m), its aerodynamic diameter d_a solves rho_0 d_a^2 C_c(d_a) = 18 mu tau; the compact sphere's
  // rho_p d_v^2 C_c(d_v) puts it above 2.5 um (negative control), the aggregate's below.
  const Air a;
  const double rp = 25e-9, n = std::pow(1.5e-6 / rp, 3);
  SampleSet p;
  p.structure_laws = {fractal_law(rp, 1.8, 1.3)};
  add_aggregate(p, a, n, rp, 1.0, 0.0);
  const double m = p.mass[0], dm = 2.0 * law_radius(n, rp, 1.8, 1.3);
  const double settling = 18.0 * a.gas.viscosity * m * a.gas.slip_correction(dm) / (3.0 * pi * a.gas.viscosity * dm);
  const double cut = 1000.0 * 2.5e-6 * 2.5e-6 * a.gas.slip_correction(2.5e-6);
  ASSERT_LT(settling, cut);
  const double dv = p.volume_diameter(0);
  ASSERT_GT(2500.0 * dv * dv * a.gas.slip_correction(dv), cut);  // the compact sphere is above the cut
  const PmMass pm = pm_mass(p, 1.0, a.gas);
  EXPECT_EQ(pm.volume[1], 0.0);           // d_v = 3 um > 2.5 um
  EXPECT_EQ(pm.aerodynamic[1], m);        // but it settles as a sphere below 2.5 um
  EXPECT_EQ(pm.aerodynamic[2], m);
}
