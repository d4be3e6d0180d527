// Checkpoint and exact restart of a collision run (impact_run.hpp, impact/checkpoint.hpp): a saved
// state loads and saves to the same bytes, and a run stopped after k steps, saved, loaded into a fresh
// run and continued ends in exactly the state (payload bytes) and records (rows, snapshots) of the
// uninterrupted run, for k in the approach, just after the first contact forms, just after an
// electrostatic solve and at the end; neutral and charged (kappa_p = 15, spectral solver, pair-corrected
// hold). The solvers' warm starts alone: tests/electrostatics/test_warm_start.cpp.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/checkpoint.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/impact/impact_run.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {

struct Stop {};  // thrown by a boundary callback to stop a run

ImpactCase load_case(const std::string& stem, const std::vector<std::string>& sets) {
  Config cfg = Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/" + stem + ".toml");
  for (const auto& s : sets) cfg.apply_override(s);
  return parse_impact_case(cfg);
}

std::string payload(const ImpactState& s) {
  io::CheckpointWriter w;
  impact::write_impact_state(w, s);
  return w.bytes();
}

ImpactState load(const std::string& bytes) {
  io::CheckpointReader r(bytes, "test");
  return impact::read_impact_state(r);
}

bool same_rows(const Recorder& a, const Recorder& b) {
  if (a.rows.size() != b.rows.size() || a.snapshots.size() != b.snapshots.size()) return false;
  for (std::size_t k = 0; k < a.rows.size(); ++k) {
    const auto &x = a.rows[k], &y = b.rows[k];
    const double xs[] = {x.t, x.kinetic, x.electrostatic, x.u_over_u0, x.rg, x.rg_agglomerate};
    const double ys[] = {y.t, y.kinetic, y.electrostatic, y.u_over_u0, y.rg, y.rg_agglomerate};
    if (std::memcmp(xs, ys, sizeof xs) != 0 || x.contacts != y.contacts) return false;
  }
  for (std::size_t k = 0; k < a.snapshots.size(); ++k) {
    const auto &x = a.snapshots[k].second, &y = b.snapshots[k].second;
    if (a.snapshots[k].first != b.snapshots[k].first) return false;
    auto eq = [](const auto& u, const auto& v) {
      return u.size() == v.size() && std::memcmp(u.data(), v.data(), u.size() * sizeof(u[0])) == 0;
    };
    if (!eq(x.position, y.position) || !eq(x.velocity, y.velocity) || !eq(x.contacts, y.contacts)) return false;
  }
  return true;
}

struct Finished {
  std::string payload;  // final state
  Recorder rec;
  ImpactOutcome out;
};

Finished uninterrupted(const ImpactCase& c, const dem::Particles& relaxed) {
  Finished f;
  ImpactRun run(c, relaxed, c.projectile.speed, &f.rec);
  f.out = run.run();
  f.payload = payload(run.state());
  return f;
}

// Steps of interest in an unrecorded pass: first contact, and the first solves after it.
struct Events {
  long contact = -1;
  std::vector<long> solves;  // steps at which the electrostatics were solved
  long last = 0;
};

Events scan(const ImpactCase& c, const dem::Particles& relaxed) {
  Events e;
  ImpactRun run(c, relaxed, c.projectile.speed, nullptr);
  run.run([&](const ImpactRun& r) {
    const auto s = r.state();
    if (e.contact < 0 && s.progress.contact) e.contact = r.steps();
    if (s.has_coupling && s.coupling.step_at_solve == r.steps() && r.steps() > 0) e.solves.push_back(r.steps());
    e.last = r.steps();
  });
  return e;
}

// Stops after k steps, saves; loads into a fresh run (agglomerate as built) and continues.
void check_restart(const ImpactCase& c, const dem::Particles& relaxed, const Finished& ref, long k) {
  SCOPED_TRACE("stopped after step " + std::to_string(k));
  Recorder rec;
  std::string saved;
  ImpactRun first(c, relaxed, c.projectile.speed, &rec);
  try {
    first.run([&](const ImpactRun& r) {
      if (r.steps() == k) throw Stop{};
    });
    FAIL() << "the run ended before step " << k;
  } catch (const Stop&) {
    saved = payload(first.state());
  }
  Recorder rec2;
  ImpactRun second(c, build_agglomerate(c), c.projectile.speed, &rec2);
  second.restore(load(saved));
  EXPECT_EQ(payload(second.state()), saved) << "save -> load -> save changed the bytes";
  const auto out = second.run();
  EXPECT_TRUE(payload(second.state()) == ref.payload) << "final state differs from the uninterrupted run";
  EXPECT_TRUE(same_rows(rec2, ref.rec)) << "recorded rows or snapshots differ";
  EXPECT_EQ(out.steps, ref.out.steps);
  EXPECT_EQ(out.broken, ref.out.broken);
  EXPECT_EQ(out.t_end, ref.out.t_end);
  EXPECT_EQ(out.es_solves, ref.out.es_solves);
}

void check_case(const ImpactCase& c, bool charged) {
  const auto relaxed = relaxed_agglomerate(c);
  const Finished ref = uninterrupted(c, relaxed);
  ASSERT_TRUE(ref.out.contact);
  ASSERT_GT(ref.rec.rows.size(), 10u);
  ASSERT_GT(ref.rec.snapshots.size(), 1u);
  const Events e = scan(c, relaxed);
  ASSERT_GT(e.contact, 0);
  // A charged run costs ~1 s (a solve every few steps): fewer stops, at its telling points.
  const std::size_t n_fixed = charged ? 4 : 6;
  std::vector<long> ks{e.contact, e.last - 1};
  if (!charged) ks.insert(ks.end(), {1, e.contact / 2, e.contact + 1, (e.contact + e.last) / 2});
  if (charged) {
    ASSERT_GE(e.solves.size(), 3u);
    ks.push_back(e.solves[e.solves.size() / 2]);  // just after a solve half-way (the projectile is
                                                  // electrostatically invisible: no solve before contact)
    for (long s : e.solves)
      if (s > e.contact + 1) {
        ks.push_back(s);  // just after the first solve in contact (not the contact step)
        break;
      }
  }
  ASSERT_EQ(ks.size(), n_fixed);
  for (long k : ks) check_restart(c, relaxed, ref, k);
  // A finished run restored continues to the same outcome without a step.
  Recorder rec;
  ImpactRun done(c, build_agglomerate(c), c.projectile.speed, &rec);
  done.restore(load(ref.payload));
  EXPECT_TRUE(done.finished());
  EXPECT_EQ(done.run().steps, ref.out.steps);
  EXPECT_EQ(payload(done.state()), ref.payload);
}

}  // namespace

TEST(ImpactCheckpoint, NeutralRestartIsExact) {
  check_case(load_case("seed000_neutral_tetrahedron",
                       {"time.after_contact=1e-4", "output.snapshot_interval=2e-5", "projectile.gap_radii=0.3"}),
             false);
}

TEST(ImpactCheckpoint, ChargedRestartIsExact) {
  check_case(load_case("seed000_charged_tetrahedron_k15", {"time.after_contact=2e-5", "output.snapshot_interval=1e-5",
                                                           "projectile.gap_radii=0.3", "time.relax_time=2e-5",
                                                           "electrostatics.target_accuracy=1e-2",
                                                           "electrostatics.hold=pair_corrected"}),
             true);
}

// The error-controlled coupling's adapted threshold and measured errors are part of the state.
TEST(ImpactCheckpoint, ErrorControlledChargedRestartIsExact) {
  check_case(load_case("seed000_charged_tetrahedron_k15", {"time.after_contact=2e-5", "output.snapshot_interval=1e-5",
                                                           "projectile.gap_radii=0.3", "time.relax_time=2e-5",
                                                           "electrostatics.target_accuracy=1e-2",
                                                           "electrostatics.force_tolerance=1e-2",
                                                           "electrostatics.hold=constant"}),
             true);
}

// The extrapolated hold's previous solution is part of the state.
TEST(ImpactCheckpoint, ExtrapolatedHoldRestartIsExact) {
  check_case(load_case("seed000_charged_tetrahedron_k15", {"time.after_contact=2e-5", "output.snapshot_interval=1e-5",
                                                           "projectile.gap_radii=0.3", "time.relax_time=2e-5",
                                                           "electrostatics.target_accuracy=1e-2",
                                                           "electrostatics.force_tolerance=1e-2",
                                                           "electrostatics.hold=extrapolated"}),
             true);
}

TEST(ImpactCheckpoint, TruncatedPayloadIsRefused) {
  const auto c = load_case("seed000_neutral_tetrahedron", {"projectile.gap_radii=0.3"});
  ImpactRun run(c, build_agglomerate(c), c.projectile.speed, nullptr);
  const std::string bytes = payload(run.state());
  EXPECT_THROW(load(bytes.substr(0, bytes.size() - 3)), ConfigError);
  EXPECT_THROW(load(bytes + "x"), ConfigError);
}

TEST(ImpactCheckpoint, WallAndGasRestartIsExact) {
  // The agglomerate flying onto a wall in air (wall contact states, drag, gravity).
  check_case(load_case("agglomerate_wall_gas", {"time.after_contact=1e-4", "output.snapshot_interval=2e-5"}), false);
}
