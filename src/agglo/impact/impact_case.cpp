#include "agglo/impact/impact_case.hpp"

#include <cmath>

#include "agglo/core/error.hpp"

namespace agglo::impact {

ImpactCase parse_impact_case(Config& cfg) {
  ImpactCase c;
  auto root = cfg.root();
  c.name = root.string("name", std::string("collision"));

  auto mat = root.section("material");
  c.agglomerate.density = mat.number("density", 2500.0, Range::positive("kg/m^3"));
  auto& cp = c.dem.contact;
  cp.youngs_modulus = mat.number("youngs_modulus", 1.0e9, Range::positive("Pa"));
  cp.poisson_ratio = mat.number("poisson_ratio", 0.33, Range::open(-1.0, 0.5));
  cp.surface_energy = mat.number("surface_energy", 0.01, Range::positive("J/m^2"));
  cp.restitution = mat.number("restitution", 0.7, Range::open_closed(0.0, 1.0));
  cp.friction = mat.number("friction", 0.3, Range::nonnegative());
  const double real_modulus =
      mat.number("real_youngs_modulus", 0.0, Range::nonnegative("Pa (0 = same as youngs_modulus)"));

  auto con = root.section("contact");
  cp.tangential = con.choice("tangential", std::string("seed"), {"seed", "marshall"}) == "seed"
                      ? dem::TangentialModel::seed
                      : dem::TangentialModel::marshall;
  cp.rolling = con.boolean("rolling", false);
  cp.twisting = con.boolean("twisting", false);
  cp.rolling_angle = con.number("rolling_angle", 0.01, Range::positive("rad"));
  cp.break_rule = con.choice("break_rule", std::string("marshall"), {"marshall", "lammps"}) == "marshall"
                      ? dem::BreakRule::marshall
                      : dem::BreakRule::lammps;
  cp.damping = con.boolean("damping", true);
  if ((cp.rolling || cp.twisting) && cp.tangential != dem::TangentialModel::marshall)
    con.fail_value(cp.rolling ? "rolling" : "twisting", "rolling/twisting resistance needs tangential = \"marshall\"");

  auto ts = root.section("time");
  c.dem.dt = ts.number("dt", 0.0, Range::nonnegative("s (0 = T0/steps_per_period)"));
  c.dem.steps_per_period = ts.number("steps_per_period", 50.0, Range::closed(10.0, 1e6));
  c.time.after_contact = ts.number("after_contact", 2e-3, Range::positive("s"));
  c.time.max_approach = ts.number("max_approach", 0.0, Range::nonnegative("s (0 = automatic)"));
  c.time.extension = ts.number("extension", 1e-3, Range::positive("s"));
  c.time.max_extensions = static_cast<int>(ts.integer("max_extensions", 4, 0, 100));
  c.time.relax_time = ts.number("relax_time", 1e-3, Range::nonnegative("s"));
  c.time.relax_energy = ts.number("relax_energy", 1e-6, Range::positive("F_C delta_C"));
  c.time.early_stop = ts.boolean("early_stop", true);
  c.time.early_stop_gap = ts.number("early_stop_gap", 2.0, Range::positive("r_p"));

  auto ag = root.section("agglomerate");
  auto& a = c.agglomerate;
  a.shape = ag.choice("shape", std::string("tetrahedron"), {"tetrahedron", "square", "list"});
  a.radius = ag.number("radius", 10e-6, Range::positive("m"));
  a.charged = ag.boolean("charged", false);
  a.charge_density = ag.number("charge_density", 10e-6, Range::nonnegative("C/m^2"));
  a.permittivity = ag.number("permittivity", 1.0, Range::positive());
  auto plist = root.tables("particles");
  if (a.shape == "list") {
    if (plist.size() < 2) ag.fail_value("shape", "shape = \"list\" needs at least two [[particles]] entries");
    for (auto& ps : plist) {
      ListParticle lp;
      lp.position = ps.vec3("position", std::nullopt, Range::any("m"));
      lp.radius = ps.number("radius", std::nullopt, Range::positive("m"));
      lp.charge = ps.number("charge", 0.0, Range::any("C"));
      lp.permittivity = ps.number("permittivity", 1.0, Range::positive());
      a.particles.push_back(lp);
    }
  } else if (!plist.empty()) {
    ag.fail_value("shape", "[[particles]] entries are only used with shape = \"list\"");
  }

  auto pj = root.section("projectile");
  auto& p = c.projectile;
  p.speed = pj.number("speed", 0.18, Range::nonnegative("m/s"));
  p.offset_radii = pj.number("offset_radii", 0.05, Range::any("r_p"));
  p.gap_radii = pj.number("gap_radii", 1.0, Range::positive("r_p"));
  p.radius = pj.number("radius", a.radius, Range::positive("m"));
  p.charge = pj.number("charge", 0.0, Range::any("C"));
  p.permittivity = pj.number("permittivity", 1.0, Range::positive());

  auto out = root.section("output");
  c.output.timeseries_interval = out.number("timeseries_interval", 5e-6, Range::positive("s"));
  c.output.snapshot_interval = out.number("snapshot_interval", 1e-4, Range::nonnegative("s (0 = none)"));

  auto vc = root.section("vcrit");
  c.vcrit.v_min = vc.number("v_min", 0.02, Range::positive("m/s"));
  c.vcrit.v_max = vc.number("v_max", 0.6, Range::positive("m/s"));
  if (c.vcrit.v_max <= c.vcrit.v_min) vc.fail_value("v_max", "must be larger than vcrit.v_min");
  c.vcrit.scan_points = static_cast<int>(vc.integer("scan_points", 12, 3, 1000));
  c.vcrit.tolerance = vc.number("tolerance", 5e-4, Range::positive("m/s"));

  auto bu = root.section("breakup");
  std::vector<double> grid(c.vcrit.scan_points);
  for (int k = 0; k < c.vcrit.scan_points; ++k)
    grid[k] = c.vcrit.v_min + (c.vcrit.v_max - c.vcrit.v_min) * k / (c.vcrit.scan_points - 1);
  c.breakup.speeds = bu.numbers("speeds", grid, Range::positive("m/s"));
  if (c.breakup.speeds.empty()) bu.fail_value("speeds", "needs at least one speed");
  c.breakup.samples = static_cast<int>(bu.integer("samples", 16, 1, 100000));
  c.breakup.offset_spread = bu.number("offset_spread", 0.05, Range::nonnegative("r_p"));

  bool any_charge = a.charged && a.charge_density > 0.0;
  for (const auto& lp : a.particles) any_charge = any_charge || lp.charge != 0.0;
  any_charge = any_charge || p.charge != 0.0;
  c.electrostatics = any_charge;
  if (c.electrostatics || root.has("electrostatics")) {
    c.coupling.es = es::parse_electrostatics(root.section("electrostatics"));
    if (c.coupling.es.force_scale_chi) {
      if (real_modulus <= 0.0)
        mat.fail_value("real_youngs_modulus", "electrostatics.force_scale_chi = true needs the real modulus (> 0 Pa)");
      c.coupling.force_scale = std::pow(cp.youngs_modulus / real_modulus, 0.4);
    }
    c.medium_permittivity = c.coupling.es.medium_permittivity;
    c.electrostatics = c.electrostatics || norm(c.coupling.es.external_field) > 0.0;
  }
  return c;
}

}  // namespace agglo::impact
