// The free flight shared by the runs of a case (impact/approach_cache.hpp): runs of the seed tetrahedron
// (neutral; kappa_p = 1 with its electrostatic coupling) that start from the cache end in the same
// particle state, bit for bit, with the same steps and solves as runs integrating their own approach,
// at speeds from the scan's slowest to beyond v_crit and at two offsets; the cache did replace most
// of the approach (negative control of a vacuous pass), a run one part in 1e9 faster ends elsewhere
// (the comparison resolves the state), and cases where the projectile is not free do not use it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/impact/approach_cache.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/impact/impact_run.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace shared_flight {

ImpactCase load_case(const std::string& name, const std::vector<std::string>& sets = {}) {
  Config cfg = Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/" + name);
  for (const auto& s : sets) cfg.apply_override(s);
  return parse_impact_case(cfg);
}

struct End {
  ImpactState state;
  ImpactOutcome outcome;
  long shared = 0;
  long approach_steps = 0;
};

End run(const ImpactCase& c, const dem::Particles& relaxed, double v, ApproachCache* cache) {
  ImpactRun r(c, relaxed, v, nullptr);
  r.share_free_flight(cache);
  End e;
  e.outcome = r.run();
  e.state = r.state();
  e.shared = r.shared_steps();
  e.approach_steps = static_cast<long>(e.outcome.t_contact / e.outcome.dt);
  return e;
}

// Every component equal (bits, but the sign of zero).
bool same_vectors(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!(a[k].x == b[k].x && a[k].y == b[k].y && a[k].z == b[k].z)) return false;
  return true;
}

bool same_particles(const dem::Particles& a, const dem::Particles& b) {
  return same_vectors(a.x, b.x) && same_vectors(a.v, b.v) && same_vectors(a.w, b.w) && same_vectors(a.f, b.f) &&
         same_vectors(a.t, b.t);
}

}  // namespace shared_flight

TEST(ApproachCache, RunsFromTheCacheEndInTheSameState) {
  for (const std::string name : {"seed000_neutral_tetrahedron.toml", "seed000_charged_tetrahedron_k1.toml"}) {
    const ImpactCase base = shared_flight::load_case(name);
    ASSERT_TRUE(ApproachCache::applies(base));
    const dem::Particles relaxed = relaxed_agglomerate(base);
    ApproachCache cache(base, relaxed);  // one cache for both offsets, as impact_batch shares it
    for (double offset : {0.05, -0.2}) {
      ImpactCase c = base;
      c.projectile.offset_radii = offset;
      c.time.bisection = true;
      for (double v : {0.02, 0.125, 0.175, 0.2, 0.3}) {
        const shared_flight::End own = shared_flight::run(c, relaxed, v, nullptr), shared = shared_flight::run(c, relaxed, v, &cache);
        const std::string at = name + " offset " + std::to_string(offset) + " v " + std::to_string(v);
        EXPECT_EQ(own.shared, 0) << at;
        // Most of the approach comes from the cache (within two strides of the first contact).
        EXPECT_GT(shared.shared, own.approach_steps - 2 * ApproachCache::kStride) << at;
        EXPECT_TRUE(shared_flight::same_particles(own.state.dem.particles, shared.state.dem.particles)) << at;
        EXPECT_EQ(own.outcome.steps, shared.outcome.steps) << at;
        EXPECT_EQ(own.outcome.t_contact, shared.outcome.t_contact) << at;
        EXPECT_EQ(own.outcome.broken, shared.outcome.broken) << at;
        EXPECT_EQ(own.outcome.breakage.rg_after, shared.outcome.breakage.rg_after) << at;
        EXPECT_EQ(own.outcome.es_solves, shared.outcome.es_solves) << at;
      }
    }
  }
}

// The spectral solver (kappa_p = 15, error-controlled re-solves; cut short): the coupling state (held forces,
// warm start, adapted threshold) comes from the cache with the agglomerate's, and the projectile (kappa_p = 1,
// uncharged) stays outside the solve.
TEST(ApproachCache, SpectralRunsEndInTheSameState) {
  for (const char* hold : {"hold=\"constant\"", "hold=\"extrapolated\""}) {
    ImpactCase c =
        shared_flight::load_case("seed000_charged_tetrahedron_k15.toml",
                                 {"time.after_contact=2e-5", "projectile.gap_radii=0.3", "time.relax_time=2e-5",
                                  "electrostatics.target_accuracy=1e-2", std::string("electrostatics.") + hold});
    ASSERT_TRUE(ApproachCache::applies(c));
    const dem::Particles relaxed = relaxed_agglomerate(c);
    ApproachCache cache(c, relaxed);
    for (double v : {0.1}) {
      const shared_flight::End own = shared_flight::run(c, relaxed, v, nullptr);
      const shared_flight::End shared = shared_flight::run(c, relaxed, v, &cache);
      EXPECT_GT(shared.shared, own.approach_steps - 2 * ApproachCache::kStride) << v;
      EXPECT_GT(own.outcome.es_solves, 0) << v;
      EXPECT_TRUE(shared_flight::same_particles(own.state.dem.particles, shared.state.dem.particles)) << v;
      EXPECT_EQ(own.outcome.steps, shared.outcome.steps) << v;
      EXPECT_EQ(own.outcome.es_solves, shared.outcome.es_solves) << v;
      EXPECT_TRUE(shared_flight::same_vectors(own.state.coupling.force, shared.state.coupling.force)) << v;
      EXPECT_EQ(own.state.coupling.solution_energy, shared.state.coupling.solution_energy) << v;
      EXPECT_EQ(own.state.coupling.fraction, shared.state.coupling.fraction) << v;
      EXPECT_TRUE(shared_flight::same_vectors(own.state.coupling.prev_force, shared.state.coupling.prev_force)) << v;
      EXPECT_EQ(own.state.coupling.step_at_prev, shared.state.coupling.step_at_prev) << v;
    }
  }
}

// Beyond its memory budget the cache keeps no more states: a run takes what there is and integrates the rest.
TEST(ApproachCache, ABudgetOfAFewStates) {
  ImpactCase c = shared_flight::load_case("seed000_neutral_tetrahedron.toml");
  c.time.bisection = true;
  const dem::Particles relaxed = relaxed_agglomerate(c);
  ApproachCache one(c, relaxed, 1.0);  // bytes: the first state only
  EXPECT_NE(one.at(0), nullptr);
  EXPECT_EQ(one.at(1), nullptr);
  ApproachCache few(c, relaxed, 1e4);  // a few states of the tetrahedron (about 2 kB each)
  const shared_flight::End own = shared_flight::run(c, relaxed, 0.02, nullptr);
  const shared_flight::End shared = shared_flight::run(c, relaxed, 0.02, &few);
  EXPECT_GT(shared.shared, 0);
  EXPECT_LT(shared.shared, own.approach_steps / 2);
  EXPECT_TRUE(shared_flight::same_particles(own.state.dem.particles, shared.state.dem.particles));
  EXPECT_EQ(own.outcome.steps, shared.outcome.steps);
}

TEST(ApproachCache, TheComparisonResolvesTheState) {
  ImpactCase c = shared_flight::load_case("seed000_neutral_tetrahedron.toml");
  c.time.bisection = true;
  const dem::Particles relaxed = relaxed_agglomerate(c);
  ApproachCache cache(c, relaxed);
  const shared_flight::End a = shared_flight::run(c, relaxed, 0.175, &cache), b = shared_flight::run(c, relaxed, 0.175 * (1.0 + 1e-9), &cache);
  EXPECT_FALSE(shared_flight::same_particles(a.state.dem.particles, b.state.dem.particles));
}

TEST(ApproachCache, NotForAProjectileThatFeelsForces) {
  ImpactCase c = shared_flight::load_case("seed000_neutral_tetrahedron.toml");
  EXPECT_TRUE(ApproachCache::applies(c));
  ImpactCase g = c;
  g.dem.gravity = {0.0, 0.0, -9.81};
  EXPECT_FALSE(ApproachCache::applies(g));
  ImpactCase gas = c;
  gas.dem.gas.enabled = true;
  EXPECT_FALSE(ApproachCache::applies(gas));
  // A charged projectile enters the electrostatic solve: the run integrates its own approach.
  ImpactCase q = shared_flight::load_case("seed000_charged_tetrahedron_k1.toml", {"projectile.charge=1e-16"});
  ASSERT_TRUE(ApproachCache::applies(q));
  const dem::Particles relaxed = relaxed_agglomerate(q);
  ApproachCache cache(q, relaxed);
  EXPECT_EQ(shared_flight::run(q, relaxed, 0.3, &cache).shared, 0);
}
