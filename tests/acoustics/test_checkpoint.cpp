// Exact restart of acoustic runs (acoustics/checkpoint.hpp, docs/restart.md): the saved state reloads
// to the same bytes, and a run resumed from a checkpoint taken after any step, or from a cancelled
// run, gives the uninterrupted run's observations and final state bit for bit.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <regex>
#include <string>
#include <vector>

#include "agglo/acoustics/checkpoint.hpp"
#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/core/error.hpp"
#include "helpers.hpp"
#include "outcome_table_helpers.hpp"

namespace agglo::acoustics {
namespace {

// A short acoustic case with droplets (Nanbu selection, exact integrator, sound): 3 acoustic periods.
// PSDs and snapshots at step 40 (t = 2e-3 s); efficiency rows every 8 steps.
std::string sound_case(const std::string& extra = "") {
  return test::standing_wave_case({}, R"(
[output]
efficiency_interval = 2e-4
psd_times = [0.0, 1e-3]
snapshot_times = [1e-3]
)" + extra);
}

// Brownian coagulation of one lognormal population of droplets in the 1 m^3 box (test::kCoagulationBox),
// with the [time] section and the box edits given.
std::string coagulation_case(int seed, const std::string& time, double concentration, int samples,
                             bool many_cells) {
  std::string box = test::kCoagulationBox;
  if (many_cells) {  // 1000 cells, gravity on: samples move between cells
    box.replace(box.find("cells_x = 1\n"), 12, "cells_x = 10\ncells_y = 10\ncells_z = 10\n");
    box.replace(box.find("gravity = false"), 15, "gravity = true");
  }
  return fmt::format("seed = {}\n{}[time]\n{}", seed, box, time) + fmt::format(R"(
[[population]]
name = "particles"
phase = "liquid"
distribution = "lognormal"
geometric_mean_diameter = 0.2e-6
geometric_std = 2.0
number_concentration = {:g}
samples = {}
[kernels]
model = "brownian_partmc"
[outcomes]
always_coalesce = true
[output]
efficiency_interval = 100.0
psd_times = [0.0, 320.0]
)", concentration, samples);
}

// Coagulation only, no motion, binned selection (groups kept between steps, bounds recomputed every
// kRetightenEvery steps): the persistent group state must survive the restart. 80 steps unless `steps`.
std::string binned_case(int steps = 80) {
  return coagulation_case(3, fmt::format("end = {}.0\ncollision_dt = 10.0\nintegrator = \"none\"\n"
                                         "initial_velocity = \"rest\"\nselection = \"binned\"\n", 10 * steps),
                          5e11, 3000, false);
}

// Enough samples (kReorderMinSamples = 1e5) that the engine re-sorts them by cell every 64 steps
// (steps 1, 65, 129, ...), with motion (gravity) so that the order changes. 67 steps.
std::string reorder_case() {
  return coagulation_case(11, "end = 670.0\ncollision_dt = 10.0\nmotion_dt = 10.0\nintegrator = \"exact\"\n"
                          "selection = \"nanbu\"\n", 5e9, 100000, true);
}

struct Outcome {
  AcousticObservations obs;
  std::vector<std::uint64_t> steps;   // of the checkpoints written
  std::vector<std::string> payloads;
};

// Runs the case with checkpoints every `interval` simulated seconds (and at the end), from `resume` if
// given; keeps the payloads of the steps in `keep` and of the last checkpoint (all when `keep` is empty).
Outcome run(const AcousticCase& c, double interval, const std::string* resume = nullptr,
            std::function<bool()> cancelled = {}, const std::vector<std::uint64_t>& keep = {}) {
  Outcome o;
  RunHooks h;
  h.checkpoint_interval = interval;
  h.checkpoint = [&](std::uint64_t step, double, const std::string& payload) {
    if (!keep.empty() && !o.steps.empty() && std::find(keep.begin(), keep.end(), o.steps.back()) == keep.end()) {
      o.steps.pop_back();
      o.payloads.pop_back();
    }
    o.steps.push_back(step);
    o.payloads.push_back(payload);
  };
  h.cancelled = std::move(cancelled);
  std::optional<io::CheckpointReader> reader;
  if (resume) reader.emplace(*resume, "test checkpoint");
  h.resume = reader ? &*reader : nullptr;
  o.obs = run_acoustic(c, h);
  return o;
}

// Everything a run reports, as bytes (run.log without its wall time).
std::string observed(AcousticObservations o) {
  o.log = std::regex_replace(o.log, std::regex("wall_time=[0-9.]+ s"), "wall_time=X");
  io::CheckpointWriter w;
  save_observations(o, w);
  w.pod(o.final);
  w.pod(o.stats);
  w.u64(o.steps);
  w.u64(o.samples);
  w.str(o.interrupted);
  return w.bytes();
}

// Takes checkpoints after every step of the case (keeping those of the steps `ks`), resumes from each of
// them (on 1 or 2 threads) and compares with the uninterrupted run without checkpoints.
void expect_resume_exact(const AcousticCase& c, const std::vector<std::uint64_t>& ks, std::uint64_t min_collisions) {
  const Outcome full = run(c, 1e9);
  ASSERT_GE(full.obs.stats.collisions, min_collisions) << "a case without collisions would test little";
  const Outcome every = run(c, c.engine.collision_dt, nullptr, {}, ks);
  ASSERT_EQ(every.steps.size(), ks.size() + 1);
  EXPECT_TRUE(every.payloads.back() == full.payloads.back()) << "writing checkpoints changed the run";
  EXPECT_TRUE(observed(every.obs) == observed(full.obs)) << "writing checkpoints changed the observations";
  const int threads = omp_get_max_threads();
  for (std::size_t i = 0; i < ks.size(); ++i) {
    ASSERT_EQ(every.steps[i], ks[i]);
    omp_set_num_threads(1 + static_cast<int>(ks[i] % 2));
    const Outcome resumed = run(c, 1e9, &every.payloads[i]);
    omp_set_num_threads(threads);
    ASSERT_EQ(resumed.payloads.size(), 1u) << "only the final checkpoint";
    EXPECT_TRUE(resumed.payloads.back() == full.payloads.back()) << "final state differs after a resume at step "
                                                                 << ks[i];
    EXPECT_TRUE(observed(resumed.obs) == observed(full.obs)) << "observations differ after a resume at step " << ks[i];
  }
}

// sound_case with fractal fines (docs/acoustics.md §1.8): the primary counts and radii are saved too.
std::string fractal_sound_case() {
  std::string s = sound_case();
  const std::string fines = "samples = 1500\n";
  s.insert(s.find(fines) + fines.size(),
           "structure = \"fractal\"\nprimary_radius = 5e-8\nfractal_dimension = 1.8\nfractal_prefactor = 1.3\n");
  return s;
}

// sound_case with charged fines (sigma = 1e-5 C/m^2) and a dry table whose P_stick depends on the charges
// (docs/acoustics.md §1.7): the samples' charges are saved too.
std::string charged_sound_case() {
  OutcomeTable t;
  t.axes = {std::vector<double>{1e-4, 100.0}, {1e-9, 1e-3}, {1e-9, 1e-3}, {-1e-3, 1e-3}, {-1e-3, 1e-3}, {}};
  for (int node = 0; node < 32; ++node) {
    t.p_stick.push_back((node & 2) ? 0.9 : 0.1);  // bit 1: the upper node of charge_1
    t.p_bounce.push_back(1.0 - t.p_stick.back());
    t.p_break.push_back(0.0);
  }
  const std::string file = test::write_table_dataset(outcome_table_dataset(t), "checkpoint_charged").string();
  std::string s = sound_case(fmt::format("[outcomes]\ndry_model = \"table\"\ntable = \"{}\"\n", file));
  const std::string fines = "samples = 1500\n";
  s.insert(s.find(fines) + fines.size(), "charge_density = 1e-5\n");
  return s;
}

TEST(AcousticCheckpoint, SaveLoadSaveGivesTheSameBytes) {
  for (const std::string& toml : {sound_case(), binned_case(), fractal_sound_case(), charged_sound_case()}) {
    const AcousticCase c = test::parse_case(toml);
    Engine e(c.engine);
    for (int s = 0; s < 37; ++s) e.step();
    io::CheckpointWriter w1;
    save_engine(e, w1);
    Engine fresh(c.engine);
    io::CheckpointReader r(w1.bytes(), "test");
    load_engine(fresh, r);
    EXPECT_TRUE(r.at_end());
    io::CheckpointWriter w2;
    save_engine(fresh, w2);
    EXPECT_EQ(fresh.step_index(), 37u);
    EXPECT_EQ(fresh.particles().q, e.particles().q);  // charged case: the charges; else both empty
    EXPECT_TRUE(w1.bytes() == w2.bytes());
    // and the reloaded engine goes on exactly as the original
    e.step();
    fresh.step();
    io::CheckpointWriter a, b;
    save_engine(e, a);
    save_engine(fresh, b);
    EXPECT_TRUE(a.bytes() == b.bytes());
  }
}

TEST(AcousticCheckpoint, ResumeAfterAnyStepEqualsTheUninterruptedRun) {
  const AcousticCase c = test::parse_case(sound_case());
  const Outcome full = run(c, 1e9);
  ASSERT_EQ(full.steps, std::vector<std::uint64_t>{60});  // the end only
  ASSERT_EQ(full.obs.psd.size(), 2u);
  // 1: first step; 7, 8, 9: around an efficiency row; 39, 40, 41: around the PSD and snapshot time; 59: last step.
  expect_resume_exact(c, {1, 7, 8, 9, 39, 40, 41, 59}, 1);
}

TEST(AcousticCheckpoint, ResumeKeepsTheBinnedGroups) {
  static_assert(kRetightenEvery == 1024, "resume around the first recomputation of the bounds");
  const AcousticCase c = test::parse_case(binned_case(1030));
  expect_resume_exact(c, {5, 1023, 1024, 1025}, 100);  // bounds of the kept groups recomputed at step 1024
}

TEST(AcousticCheckpoint, ResumeAroundASampleReorder) {
  const AcousticCase c = test::parse_case(reorder_case());
  expect_resume_exact(c, {1, 64, 65, 66}, 100);  // re-sorted in steps 1 and 65
}

TEST(AcousticCheckpoint, CancelledRunWritesItsStateAndResumesExactly) {
  const AcousticCase c = test::parse_case(binned_case());  // 80 steps
  const Outcome full = run(c, 1e9);
  int checks = 0;
  const Outcome stopped = run(c, 1e9, nullptr, [&] { return ++checks == 1; });  // cancelled at step 64
  ASSERT_FALSE(stopped.obs.interrupted.empty());
  ASSERT_EQ(stopped.steps, std::vector<std::uint64_t>{64});
  const Outcome resumed = run(c, 1e9, &stopped.payloads.back());
  EXPECT_TRUE(resumed.payloads.back() == full.payloads.back());
  EXPECT_TRUE(observed(resumed.obs) == observed(full.obs));
}

TEST(AcousticCheckpoint, PeriodicCheckpointsAtEveryCrossing) {
  const AcousticCase c = test::parse_case(sound_case());
  const Outcome o = run(c, 4e-4);  // 16 steps of 2.5e-5 s; the end (step 60) is not a multiple
  EXPECT_EQ(o.steps, (std::vector<std::uint64_t>{16, 32, 48, 60}));
  const Outcome none = run(c, 0.0);
  EXPECT_TRUE(none.steps.empty());
}

TEST(AcousticCheckpoint, PayloadOfAnotherCaseIsRefused) {
  const AcousticCase a = test::parse_case(sound_case());
  const AcousticCase b = test::parse_case(binned_case());
  const Outcome o = run(a, 1e9);
  Engine e(b.engine);
  io::CheckpointReader r(o.payloads.back(), "other.bin");
  EXPECT_THROW(load_engine(e, r), ConfigError);
}

}  // namespace
}  // namespace agglo::acoustics
