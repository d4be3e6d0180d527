#pragma once
// The agglomerate-collision experiment of Ruan & Li (2022), docs/model.md §A.3: a particle hits a small
// agglomerate at speed v_in; break-up is classified at the end. This header holds the validated
// case description (parsed from TOML by parse_impact_case; every key listed in docs/config.md).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/core/rotation.hpp"
#include "agglo/core/settings_impact.hpp"
#include "agglo/core/vec3.hpp"
#include "agglo/impact/electrostatic_coupling.hpp"
#include "agglo/dem/dem_system.hpp"
#include "agglo/electrostatics/config.hpp"
#include "agglo/structure/aggregate.hpp"

namespace agglo::impact {

// Defaults below come from the declared settings (agglo/core/settings_impact.hpp), the one place
// where keys, defaults and ranges are written.
inline const settings::ImpactSettings& impact_keys() { return settings::impact_settings(); }

using ListParticle = es::ParticleEntry;  // one [[particles]] entry (shape = "list")

struct AgglomerateSpec {
  std::string shape = std::string(impact_keys().agglomerate.shape.def());  // tetrahedron | square | list
  double radius = impact_keys().agglomerate.radius.def();                 // r_p [m] (built-in shapes)
  double density = impact_keys().material.density.def();                 // rho_p [kg/m^3]
  bool charged = impact_keys().agglomerate.charged.def();                 // alternate +/- sigma_f (built-in shapes)
  double charge_density = impact_keys().agglomerate.charge_density.def(); // |sigma_f| [C/m^2]
  double permittivity = impact_keys().agglomerate.permittivity.def();     // kappa_p (built-in shapes)
  // edge_across | edge_along | face | vertex (orientation.hpp); empty = the shape's original geometry
  std::string orientation;
  std::vector<ListParticle> particles;                                    // shape = list
  // shape = fractal | bpca | bcca | file (impact/structure_target.hpp): the request, and the structure
  // built (or read) and checked at parse time, primaries touching, centroid at the origin.
  int primaries = static_cast<int>(impact_keys().agglomerate.primaries.def());           // N
  double fractal_dimension = impact_keys().agglomerate.fractal_dimension.def();          // D_f
  double fractal_prefactor = impact_keys().agglomerate.fractal_prefactor.def();          // k_f
  double radius_std = impact_keys().agglomerate.radius_std.def();                        // sigma_g
  std::string file;                                                                      // resolved path
  long long seed = impact_keys().agglomerate.seed.def();
  structure::Aggregate structure;
  // Materials (dem/material.hpp): `material` of every primary (agglomerate.material), or per primary
  // of the list and file shapes (particles.material, the file's material column); empty: all `material`.
  std::uint32_t material = 0;
  std::vector<std::uint32_t> materials;
  std::uint32_t material_of(std::size_t k) const { return k < materials.size() ? materials[k] : material; }
};

struct ProjectileSpec {
  double speed = impact_keys().projectile.speed.def();                // v_in [m/s]
  double offset_radii = impact_keys().projectile.offset_radii.def();  // lateral offset along y [r_p]
  double gap_radii = impact_keys().projectile.gap_radii.def();        // initial surface gap [r_p]
  double radius = impact_keys().agglomerate.radius.def();             // [m]; default: the agglomerate radius
  double charge = impact_keys().projectile.charge.def();              // [C]
  double permittivity = impact_keys().projectile.permittivity.def();  // kappa_p
  std::uint32_t material = 0;                                         // material id (dem/material.hpp)
  // An aggregate projectile (projectile.shape fractal | bpca | bcca | file; "sphere": the sphere above):
  // the builder's request and structure in `body` (radius = the primary radius a_g above, materials),
  // turned about its centroid by `rotation` (projectile.orientation = "random": drawn from the seed).
  std::string shape = "sphere";
  AgglomerateSpec body;
  Rotation rotation;
};

struct TimeSpec {
  double after_contact = impact_keys().time.after_contact.def();  // run time after the first contact [s]
  double max_approach = impact_keys().time.max_approach.def();    // [s]; 0 = 5x the ballistic time
  double extension = impact_keys().time.extension.def();          // extra time when undecided [s]
  int max_extensions = static_cast<int>(impact_keys().time.max_extensions.def());
  double relax_time = impact_keys().time.relax_time.def();      // max relaxation before launch [s]
  double relax_energy = impact_keys().time.relax_energy.def();  // relaxed when E_kin < this x F_C delta_C
  bool early_stop = impact_keys().time.early_stop.def();        // stop once clearly broken
  double early_stop_gap = impact_keys().time.early_stop_gap.def();  // ... fragments this far apart [r_p]
  std::string intact_stop = "vcrit";  // time.intact_stop: stop once provably intact (intact.hpp) in "vcrit" bisections, "on", "off"
  bool bisection = false;             // a run of a v_crit bisection (set by the search, run::speed_batch)
};

struct OutputSpec {
  double timeseries_interval = impact_keys().output.timeseries_interval.def();  // [s]
  double snapshot_interval = impact_keys().output.snapshot_interval.def();      // [s]; 0 = no VTK snapshots
};

struct VcritSpec {
  double v_min = impact_keys().vcrit.v_min.def();                               // [m/s]
  double v_max = impact_keys().vcrit.v_max.def();                               // [m/s]
  int scan_points = static_cast<int>(impact_keys().vcrit.scan_points.def());    // coarse linear scan
  double tolerance = impact_keys().vcrit.tolerance.def();                       // bisection tolerance [m/s]
  // Speeds tried per bisection round: fixed by configuration so v_crit never depends on the core count.
  int points_per_round = static_cast<int>(impact_keys().vcrit.points_per_round.def());
  bool sticking = false;  // vcrit.criterion = "sticking" (vcrit.hpp); false: "breakup"
  bool top_down = false;  // vcrit.order = "top_down" (vcrit.hpp); false: "full"
};

// Break-up probability (agglo breakup): at each speed, `samples` runs whose projectile offset is
// spread evenly over offset_radii +- offset_spread (stratified, no random numbers), for each of
// `orientations` rigid rotations of the agglomerate (orientation_set.hpp; 1 = as oriented).
struct BreakupSpec {
  std::vector<double> speeds;  // [m/s]; default: the vcrit scan grid (v_min .. v_max, scan_points)
  int samples = static_cast<int>(impact_keys().breakup.samples.def());  // runs per speed
  double offset_spread = impact_keys().breakup.offset_spread.def();     // half-width of the offset range [r_p]
  int orientations = 1;  // rotations of the stratified orientation set; 1 = the agglomerate as oriented
};

struct ImpactCase {
  std::string name = std::string(impact_keys().top.name.def());
  dem::DemParams dem;
  AgglomerateSpec agglomerate;
  ProjectileSpec projectile;
  TimeSpec time;
  OutputSpec output;
  VcritSpec vcrit;
  BreakupSpec breakup;
  bool electrostatics = false;  // derived: any charge or field present
  double medium_permittivity = es::es_keys().medium_permittivity.def();  // kappa_0
  CouplingSettings coupling;    // [electrostatics]
  // [wall] (the wall itself is in dem.walls) and [gas] (dem.gas, dem.gravity): docs/dem.md "Gas and walls".
  bool wall_impact = false;     // the agglomerate moves onto the wall (no projectile)
  // Derived, not a setting: a projectile that never touches ends the run without contact (an outcome:
  // agglo outcomes with charge axes, where like charges can turn it back) instead of an InvalidRunError.
  bool miss_is_outcome = false;
};

// [agglomerate] (with [[particles]] for shape = "list", the structure of impact/structure_target.hpp for
// the builder's shapes); `case_file` locates a relative agglomerate.file. Density: the default.
// `wall_impact` (wall.impact): a list of one sphere is allowed, that sphere hitting the wall.
AgglomerateSpec parse_agglomerate(const ConfigSection& root, const std::string& case_file, bool wall_impact = false);

// Reads every section; throws ConfigError naming file, key, value and the allowed range.
// `one_sphere_target`: a list agglomerate of a single sphere is accepted without a wall (agglo outcomes:
// sphere-sphere impacts); otherwise a list needs two spheres, or one with wall.impact = true.
ImpactCase parse_impact_case(Config& cfg, bool one_sphere_target = false);

// What `agglo aggregate` reads: the name, [agglomerate] (its structure built and checked) and, when the
// case has a [material] table, [[materials]] entries or agglomerate.material, those as parse_impact_case
// reads them with the material of every primary (agglomerate.material, a file's
// material column); `materials_given` says whether it had any of them.
ImpactCase parse_aggregate_case(Config& cfg, bool& materials_given);

// Density of material id `id` [kg/m^3]: 0 = [material], k >= 1 = c.dem.materials[k - 1].
double material_density(const ImpactCase& c, std::uint32_t id);
// Name of material id `id`: "default" (0, the [material] table) or its [[materials]] name.
std::string material_name(const ImpactCase& c, std::uint32_t id);
// The names a material key accepts, "default" first, quoted and comma-separated (messages).
std::string material_names(const ImpactCase& c);

}  // namespace agglo::impact
