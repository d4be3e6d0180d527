#pragma once
// The agglomerate-collision experiment of Ruan & Li (2022), MODEL.md A.3: a particle hits a small
// agglomerate at speed v_in; break-up is classified at the end. This header holds the validated
// case description (parsed from TOML by parse_impact_case; every key documented in docs/dem.md).
#include <optional>
#include <string>
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/core/vec3.hpp"
#include "agglo/impact/electrostatic_coupling.hpp"
#include "agglo/dem/dem_system.hpp"

namespace agglo::impact {

struct ListParticle {
  Vec3 position;            // [m]
  double radius = 0.0;      // [m]
  double charge = 0.0;      // [C]
  double permittivity = 1;  // kappa_p
};

struct AgglomerateSpec {
  std::string shape = "tetrahedron";  // tetrahedron | square | list
  double radius = 10e-6;              // r_p [m] (built-in shapes)
  double density = 2500.0;            // rho_p [kg/m^3]
  bool charged = false;               // alternate +/- sigma_f (built-in shapes)
  double charge_density = 10e-6;      // |sigma_f| [C/m^2]
  double permittivity = 1.0;          // kappa_p of every agglomerate particle (built-in shapes)
  std::vector<ListParticle> particles;  // shape = list
};

struct ProjectileSpec {
  double speed = 0.18;         // v_in [m/s]
  double offset_radii = 0.05;  // lateral offset along y, in units of r_p
  double gap_radii = 1.0;      // initial surface gap, in units of r_p
  double radius = 10e-6;       // [m]
  double charge = 0.0;         // [C]
  double permittivity = 1.0;   // kappa_p
};

struct TimeSpec {
  double after_contact = 2e-3;    // run time after the first projectile contact [s]
  double max_approach = 0.0;      // give up if no contact by then [s]; 0 = 5x the ballistic time
  double extension = 1e-3;        // extra time when the outcome is undecided [s]
  int max_extensions = 4;
  double relax_time = 1e-3;       // max relaxation of the agglomerate before launch (electrostatics) [s]
  double relax_energy = 1e-6;     // relaxed when kinetic energy < this x F_C delta_C
  bool early_stop = true;         // stop once clearly broken (fragments escaping and far apart)
  double early_stop_gap = 2.0;    // ... with surface gaps to the rest of at least this x r_p
};

struct OutputSpec {
  double timeseries_interval = 5e-6;  // [s]
  double snapshot_interval = 1e-4;    // [s]; 0 = no VTK snapshots
};

struct VcritSpec {
  double v_min = 0.02;       // [m/s]
  double v_max = 0.6;        // [m/s]
  int scan_points = 12;      // coarse scan (log-spaced is not needed: linear)
  double tolerance = 5e-4;   // bisection tolerance [m/s]
  int points_per_round = 2;  // speeds tried per bisection round (fixed by configuration, not by cores)
};

// Break-up probability (agglo breakup): at each speed, `samples` runs whose projectile offset is
// spread evenly over offset_radii +- offset_spread (stratified, no random numbers).
struct BreakupSpec {
  std::vector<double> speeds;     // [m/s]; default: the vcrit scan grid (v_min .. v_max, scan_points)
  int samples = 16;               // runs per speed
  double offset_spread = 0.05;    // half-width of the offset range [r_p]
};

struct ImpactCase {
  std::string name = "collision";
  dem::DemParams dem;
  AgglomerateSpec agglomerate;
  ProjectileSpec projectile;
  TimeSpec time;
  OutputSpec output;
  VcritSpec vcrit;
  BreakupSpec breakup;
  bool electrostatics = false;          // derived: any charge or field present
  double medium_permittivity = 1.0;     // kappa_0
  CouplingSettings coupling;            // [electrostatics]
};

// Reads every section; throws ConfigError naming file, key, value and the allowed range.
ImpactCase parse_impact_case(Config& cfg);

}  // namespace agglo::impact
