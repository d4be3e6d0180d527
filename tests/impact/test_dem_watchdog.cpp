// The DEM blow-up checks of a collision run (docs/dem.md "Limits and checks"): a time step of about
// one contact period (refused by the case parser, set directly here) pumps energy into the contacts;
// the run must stop with a DemInstability instead of reporting an outcome.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "agglo/impact/experiment.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {
ImpactCase neutral_tetrahedron() {
  ImpactCase c;
  c.time.after_contact = 1e-3;
  c.output.snapshot_interval = 0.0;
  return c;
}
}  // namespace

TEST(DemWatchdog, DefaultStepRunsWithoutAlarm) {
  Recorder rec;
  const ImpactOutcome out = run_impact(neutral_tetrahedron(), 0.18, &rec);
  EXPECT_TRUE(out.contact);
  for (const auto& r : rec.rows) ASSERT_TRUE(std::isfinite(r.kinetic) && std::isfinite(r.electrostatic));
}

TEST(DemWatchdog, StepOfAboutOneContactPeriodStops) {
  ImpactCase c = neutral_tetrahedron();
  c.dem.dt = 1e-6;  // T0 = 1.15e-6 s for the default tetrahedron
  Recorder rec;
  try {
    run_impact(c, 0.18, &rec);
    FAIL() << "a run at dt ~ T0 must stop";
  } catch (const dem::DemInstability& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("energy rise at step"), std::string::npos) << msg;  // the watchdog, first
    EXPECT_NE(msg.find("particle"), std::string::npos) << msg;
    EXPECT_NE(msg.find(impact_keys().time.dt.dotted()), std::string::npos) << msg;
  }
  for (const auto& r : rec.rows) ASSERT_TRUE(std::isfinite(r.kinetic) && std::isfinite(r.electrostatic));
}
