#include "agglo/dem/jkr.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::dem {

const double kJkrCbrt6 = std::cbrt(6.0);
const double kJkrSMin = 1.0 / std::cbrt(6.0);

namespace {

// The root s(w) of (s - m) q(s)^(1/2) = w (jkr.hpp), q(s) = 2 s^2 + 4 m s + 6 m^2, m = 6^(-1/3): Newton on
// phi(s) = (s - m) q^(1/2) - w, increasing and concave-up free of the double root of f(s) = t, in long double.
// `start` (>= m): the first iterate (the root of a nearby w saves iterations at start-up).
long double root_of_w(long double w, long double start) {
  const long double m = 1.0L / std::cbrt(6.0L);
  long double s = start;
  for (int it = 0; it < 100; ++it) {
    const long double q = 2.0L * s * s + 4.0L * m * s + 6.0L * m * m;
    const long double rq = std::sqrt(q);
    const long double phi = (s - m) * rq - w;
    const long double dphi = rq + (s - m) * (4.0L * s + 4.0L * m) / (2.0L * rq);
    const long double next = std::max(s - phi / dphi, m);
    // quadratic convergence: after a step of 1e-15 s the error is of order 1e-30 s (and the test ends the loop
    // also where long double is double, e.g. under valgrind)
    const bool done = std::abs(next - s) <= 1e-15L * s;
    s = next;
    if (done) break;
  }
  return s;
}

// One cubic per cell through the roots at the cell's four Chebyshev points (solved in long double).
JkrRootTable make_root_table() {
  JkrRootTable t{};
  const long double pi = 3.141592653589793238462643383279502884L;
  const long double h = static_cast<long double>(kJkrTableW) / kJkrTableCells;
  long double node[4];
  for (int k = 0; k < 4; ++k) node[k] = 0.5L + 0.5L * std::cos((2 * k + 1) * pi / 8.0L);
  long double last = 1.0L / std::cbrt(6.0L);  // the root at w = 0
  for (int cell = 0; cell < kJkrTableCells; ++cell) {
    long double a[4][5];
    for (int k = 3; k >= 0; --k) {  // (increasing x: the Chebyshev points decrease in k)
      const long double x = node[k];
      for (int e = 0; e < 4; ++e) a[k][e] = e == 0 ? 1.0L : a[k][e - 1] * x;
      a[k][4] = last = root_of_w((cell + x) * h, last);
    }
    for (int col = 0; col < 4; ++col)  // Gauss-Jordan on the 4 x 4 Vandermonde system (well conditioned)
      for (int row = 0; row < 4; ++row) {
        if (row == col) continue;
        const long double f = a[row][col] / a[col][col];
        for (int e = col; e < 5; ++e) a[row][e] -= f * a[col][e];
      }
    for (int e = 0; e < 4; ++e) t.c[cell][e] = static_cast<double>(a[e][4] / a[e][e]);
  }
  return t;
}

}  // namespace

const JkrRootTable kJkrRootTable = make_root_table();

JkrPair JkrPair::make(double R, double Estar, double gamma) {
  JkrPair p;
  p.R = R;
  p.Estar = Estar;
  p.gamma = gamma;
  p.Fc = 3.0 * constants::pi * gamma * R;
  p.a0 = std::cbrt(9.0 * constants::pi * gamma * R * R / Estar);
  p.deltaC = p.a0 * p.a0 / (2.0 * kJkrCbrt6 * R);
  p.derive();
  return p;
}

double JkrPair::delta_of_a(double a) const {
  return a * a / R - 2.0 * std::sqrt(constants::pi * gamma * a / Estar);
}

}  // namespace agglo::dem
