// The half kicks and the drift four particles at a time (dem/kick_drift.hpp) against the same step one
// particle at a time (kick_one, x += dt v, NeighborList's |x - x_build|^2 > lim2): the same bits for every
// range (groups of four and the tail), with and without gas drag, and the same rebuild answer whichever lane
// of a group (or the tail) holds the one particle that moved beyond the limit.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "agglo/dem/kick_drift.hpp"

namespace agglo::dem {
namespace {

struct Arrays {
  std::vector<Vec3> x, v, w, f, t, xb;
  std::vector<double> kv, kw, decay, lag, m;

  explicit Arrays(std::size_t n, unsigned seed) {
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.5, 2.0);
    auto vec = [&](double s) { return Vec3{s * u(gen), s * u(gen), s * u(gen)}; };
    for (std::size_t q = 0; q < n; ++q) {
      x.push_back(vec(1e-4)), v.push_back(vec(0.3)), w.push_back(vec(1e4)), f.push_back(vec(1e-6));
      t.push_back(vec(1e-11)), xb.push_back(x.back() + vec(1e-8));  // within the limit
      m.push_back(1e-11 * pos(gen)), kv.push_back(1e-9 / m.back()), kw.push_back(1e-9 / (1e-21 * pos(gen)));
      decay.push_back(0.999 * pos(gen) / 2.0), lag.push_back(1e-9 * pos(gen));
    }
  }
  VerletArrays view(bool gas, bool tracked) {
    VerletArrays a;
    a.x = x.data(), a.v = v.data(), a.w = w.data(), a.f = f.data(), a.t = t.data();
    a.kick_v = kv.data(), a.kick_w = kw.data();
    if (gas) a.decay = decay.data(), a.lag = lag.data(), a.m = m.data(), a.u = Vec3{0.1, -0.2, 0.05};
    if (tracked) a.x_at_build = xb.data();
    a.dt = 2e-9;
    a.lim2 = 0.25 * (1.5e-7 * 1.5e-7);
    return a;
  }
};

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0);
}

// The reference: one particle at a time, as DemSystem's reference twin steps.
bool kick_drift_one_at_a_time(const VerletArrays& a, std::size_t n) {
  bool far = false;
  for (std::size_t q = 0; q < n; ++q) {
    kick_one(a, q);
    a.x[q] += a.dt * a.v[q];
    far = (a.x_at_build && norm2(a.x[q] - a.x_at_build[q]) > a.lim2) || far;
  }
  return far;
}

// The ranges a caller may give: [0, n) whole, or cut at `cut` (so that groups of four start anywhere).
bool kick_drift_in_ranges(const VerletArrays& a, std::size_t n, std::size_t cut) {
  if (cut >= n) return kick_drift(a, 0, n);
  const bool first = kick_drift(a, 0, cut);
  return kick_drift(a, cut, n) || first;
}

TEST(KickDrift, RangesEqualOneParticleAtATime) {
  for (std::size_t n : {0u, 1u, 3u, 4u, 5u, 8u, 13u, 1027u})
    for (std::size_t cut : {std::size_t{1}, std::size_t{6}, n})
      for (bool gas : {false, true})
        for (bool tracked : {false, true}) {
          Arrays ref(n, 7 + n), fast(n, 7 + n);
          if (n % 2 == 1) ref.xb[n / 2] = fast.xb[n / 2] = ref.x[n / 2] + Vec3{2e-7, 0.0, 0.0};  // one beyond
          const bool far_ref = kick_drift_one_at_a_time(ref.view(gas, tracked), n);
          const bool far_fast = kick_drift_in_ranges(fast.view(gas, tracked), n, cut);
          EXPECT_EQ(far_fast, far_ref) << "n " << n << " cut " << cut << " gas " << gas;
          EXPECT_TRUE(same_bits(fast.x, ref.x)) << "x, n " << n << " cut " << cut << " gas " << gas;
          EXPECT_TRUE(same_bits(fast.v, ref.v)) << "v, n " << n << " cut " << cut << " gas " << gas;
          EXPECT_TRUE(same_bits(fast.w, ref.w)) << "w, n " << n << " cut " << cut << " gas " << gas;
          // the closing kick on the same arrays
          for (std::size_t q = 0; q < n; ++q) kick_one(ref.view(gas, tracked), q);
          kick(fast.view(gas, tracked), 0, std::min(cut, n));
          kick(fast.view(gas, tracked), std::min(cut, n), n);
          EXPECT_TRUE(same_bits(fast.v, ref.v)) << "closing v, n " << n << " cut " << cut << " gas " << gas;
          EXPECT_TRUE(same_bits(fast.w, ref.w)) << "closing w, n " << n << " cut " << cut << " gas " << gas;
        }
}

// One particle beyond the limit, in every lane of a group of four and in the tail: the test sees it; with
// every particle inside, it sees none (the random displacements above are below the limit: checked here).
TEST(KickDrift, TheOneParticleBeyondTheLimitIsSeenInEveryLane) {
  const std::size_t n = 11;  // groups 0-3, 4-7, tail 8-10
  {
    Arrays a(n, 3);
    EXPECT_FALSE(kick_drift(a.view(false, true), 0, n)) << "no particle beyond the limit";
  }
  for (std::size_t q = 0; q < n; ++q) {
    Arrays a(n, 3);
    a.xb[q] = a.x[q] + Vec3{0.0, 0.0, 2e-7};  // 2e-7 m from where the step leaves it, beyond sqrt(lim2)
    EXPECT_TRUE(kick_drift(a.view(false, true), 0, n)) << "particle " << q;
  }
}

// Negative control: the comparison sees one ulp in one velocity component of one particle.
TEST(KickDrift, ComparisonSeesOneUlp) {
  Arrays ref(9, 5), fast(9, 5);
  fast.v[6].y = std::nextafter(fast.v[6].y, 1.0);
  kick_drift_one_at_a_time(ref.view(false, false), 9);
  kick_drift(fast.view(false, false), 0, 9);
  EXPECT_FALSE(same_bits(fast.v, ref.v));
  EXPECT_TRUE(same_bits(fast.w, ref.w));
}

}  // namespace
}  // namespace agglo::dem
