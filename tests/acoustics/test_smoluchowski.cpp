// docs/model.md §C.7.1: Smoluchowski coagulation from an exponential start, n(v,0) = N0/v0 exp(-v/v0), x = v/v0,
// with 1e5 sampled particles (the PartMC tolerances: relative L2 error over size bins <= 5 % in number and
// <= 20 % in mass; N(t) within 2 %).
//   constant K0, tau = K0 N0 t:   n = 4 N0 / (v0 (2+tau)^2) exp(-2x/(2+tau)),  N = 2 N0/(2+tau)
//   additive B(u+v), tau = B N0 v0 t, T = 1 - exp(-tau):
//                                 n = N0 (1-T) / (v sqrt(T)) exp(-(1+T) x) I1(2 x sqrt(T)),  N = N0 exp(-tau)
#include <cmath>
#include <functional>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "helpers.hpp"

using namespace agglo::acoustics;

namespace {

constexpr double kN0 = 1048576.0 * 1e5;  // per m^3 in a 1 m^3 box: weight 2^20 per sample
constexpr double kV0 = 1e-18;             // m^3

std::string case_text(const std::string& kernel_lines, double end, double dt) {
  return fmt::format(R"(
seed = 11
{}
[time]
end = {}
collision_dt = {}
integrator = "none"
[[population]]
name = "exp"
phase = "solid"
distribution = "exponential"
mean_volume = {}
number_concentration = {}
samples = 100000
[kernels]
{}
[outcomes]
always_coalesce = true
)",
                     test::kCoagulationBox, end, dt, kV0, kN0, kernel_lines);
}

struct Errors {
  double number, mass;
};

// Relative L2 errors over log-spaced bins in x = v/v0 of the number and mass per bin.
Errors l2_errors(const SampleSet& p, const std::function<double(double)>& f, double xmin, double xmax, int nb) {
  std::vector<double> ns(nb, 0.0), ms(nb, 0.0), ne(nb, 0.0), me(nb, 0.0);
  const double r = std::log(xmax / xmin) / nb;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.w[i] <= 0) continue;
    const double x = p.volume(i) / kV0;
    const int b = static_cast<int>(std::floor(std::log(x / xmin) / r));
    if (b < 0 || b >= nb) continue;
    ns[b] += p.w[i];  // box volume 1 m^3
    ms[b] += p.w[i] * x;
  }
  for (int b = 0; b < nb; ++b) {
    const double a = xmin * std::exp(r * b), c = xmin * std::exp(r * (b + 1));
    const int m = 400;  // Simpson in log x
    double sn = 0, sm = 0;
    for (int k = 0; k <= m; ++k) {
      const double x = a * std::pow(c / a, static_cast<double>(k) / m);
      const double wgt = (k == 0 || k == m) ? 1 : (k % 2 ? 4 : 2);
      sn += wgt * f(x) * x;  // dx = x dlnx
      sm += wgt * f(x) * x * x;
    }
    const double h = std::log(c / a) / m / 3;
    ne[b] = kN0 * sn * h;
    me[b] = kN0 * sm * h;
  }
  double dn = 0, en = 0, dm = 0, em = 0;
  for (int b = 0; b < nb; ++b) {
    dn += (ns[b] - ne[b]) * (ns[b] - ne[b]);
    en += ne[b] * ne[b];
    dm += (ms[b] - me[b]) * (ms[b] - me[b]);
    em += me[b] * me[b];
  }
  return {std::sqrt(dn / en), std::sqrt(dm / em)};
}

}  // namespace

TEST(Smoluchowski, ConstantKernelExponentialStart) {
  const double K0 = 1.0 / kN0;  // tau = t
  Engine e = test::make_engine(case_text(fmt::format("model = \"constant\"\nconstant_coefficient = {}", K0), 3.0, 0.01));
  ASSERT_EQ(e.particles().size(), 100000u);
  for (double tau_check : {1.0, 3.0}) {
    while (e.time() < tau_check - 1e-9) e.step();
    const double tau = e.time();
    const double N = 2.0 * kN0 / (2.0 + tau);
    EXPECT_NEAR(test::total_number(e.particles()) / N, 1.0, 0.02) << "tau " << tau;
    auto f = [tau](double x) { return 4.0 / ((2 + tau) * (2 + tau)) * std::exp(-2 * x / (2 + tau)); };
    const Errors err = l2_errors(e.particles(), f, 1e-2, 40.0, 25);
    EXPECT_LE(err.number, 0.05) << "tau " << tau;
    EXPECT_LE(err.mass, 0.20) << "tau " << tau;
    RecordProperty(fmt::format("l2_number_tau{}", tau_check), fmt::format("{:.4f}", err.number));
    std::printf("constant kernel tau=%.2f: N/N_exact=%.4f L2 number %.4f mass %.4f\n", tau,
                test::total_number(e.particles()) / N, err.number, err.mass);
  }
  // Mass (here solid volume) is conserved exactly by every coalescence.
  double vol = 0;
  for (std::size_t i = 0; i < e.particles().size(); ++i) vol += e.particles().w[i] * e.particles().vol_s[i];
  EXPECT_NEAR(vol / (kN0 * kV0), 1.0, 0.01);  // initial stratified sample has the exponential's mean to < 1 %
}

TEST(Smoluchowski, AdditiveKernelExponentialStart) {
  const double B = 1.0 / (kN0 * kV0);  // tau = t
  Engine e = test::make_engine(case_text(fmt::format("model = \"additive\"\nadditive_coefficient = {}", B), 1.0, 0.005));
  double vol0 = 0;
  for (std::size_t i = 0; i < e.particles().size(); ++i) vol0 += e.particles().w[i] * e.particles().vol_s[i];
  for (double tau_check : {0.5, 1.0}) {
    while (e.time() < tau_check - 1e-9) e.step();
    const double tau = e.time(), T = 1 - std::exp(-tau);
    EXPECT_NEAR(test::total_number(e.particles()) / (kN0 * std::exp(-tau)), 1.0, 0.02) << "tau " << tau;
    auto f = [T](double x) {
      return (1 - T) / (x * std::sqrt(T)) * std::exp(-(1 + T) * x) * std::cyl_bessel_i(1.0, 2 * x * std::sqrt(T));
    };
    const Errors err = l2_errors(e.particles(), f, 1e-2, 300.0, 30);
    EXPECT_LE(err.number, 0.05) << "tau " << tau;
    EXPECT_LE(err.mass, 0.20) << "tau " << tau;
    std::printf("additive kernel tau=%.2f: N/N_exact=%.4f L2 number %.4f mass %.4f\n", tau,
                test::total_number(e.particles()) / (kN0 * std::exp(-tau)), err.number, err.mass);
  }
  double vol = 0;
  for (std::size_t i = 0; i < e.particles().size(); ++i) vol += e.particles().w[i] * e.particles().vol_s[i];
  EXPECT_NEAR(vol / vol0, 1.0, 1e-12);
}
