#pragma once
// Settings tables of the DEM impact commands (collide, vcrit, breakup): the one declaration of each
// key, its unit, default, range and meaning (docs/dem.md describes the experiment, docs/config.md
// lists these tables). [[particles]] is in settings_electrostatics.hpp, [electrostatics] in electrostatics/keys.hpp.
#include <array>
#include <cstdint>
#include <string>

#include "agglo/core/settings.hpp"

namespace agglo::settings {

inline constexpr std::string_view kImpactCommands = "collide, vcrit, breakup, outcomes";
// [agglomerate] and the top level are read by the impact commands and by `agglo aggregate`.
inline constexpr std::string_view kAgglomerateCommands = "collide, vcrit, breakup, outcomes, aggregate";

// The keys of the structure builder (docs/model.md Part S), declared once for the two tables that build
// a structure: [agglomerate] (the target) and [projectile] (an aggregate projectile). `table` is the
// section name ("agglomerate"), `what` the body named in the meanings. The dotted keys and meanings
// are stored here, before the settings that refer to them (not copyable, like every Setting).
struct BuilderKeys {
  BuilderKeys(Table& t, std::string_view table, std::string_view what);
  std::array<std::string, 12> text_;  // dotted key, meaning of each setting below, in order
  Integer seed, primaries;
  Real fractal_dimension, fractal_prefactor, radius_std;
  Text file;
};

struct ImpactSettings {
  struct Top {
    Table t{"", kAgglomerateCommands, "top-level keys of an impact case"};
    Text name{t, {"name", "", "case name"}, "collision"};
  } top;

  struct Material {
    Table t{"material", kAgglomerateCommands, "material of every particle (contact model)"};
    Real density{t, {"material.density", "kg/m^3", "particle density rho_p"}, 2500.0, Range::open_closed(0.0, 1e5)};
    Real youngs_modulus{t, {"material.youngs_modulus", "Pa", "Young's modulus E of the contact model"}, 1.0e9,
                        Range::open_closed(0.0, 1e13)};
    Real poisson_ratio{t, {"material.poisson_ratio", "", "Poisson ratio nu"}, 0.33, Range::open(-1.0, 0.5)};
    Real surface_energy{t, {"material.surface_energy", "J/m^2", "surface energy gamma of the JKR adhesion"}, 0.01,
                        Range::open_closed(0.0, 100.0)};
    Real restitution{t, {"material.restitution", "", "normal coefficient of restitution e"}, 0.7,
                     Range::open_closed(0.0, 1.0)};
    Real friction{t, {"material.friction", "", "sliding friction coefficient mu_F"}, 0.3, Range::closed(0.0, 10.0)};
    Real real_youngs_modulus{t,
                             {"material.real_youngs_modulus", "Pa",
                              "real Young's modulus; electrostatic forces are scaled by (E/E_real)^(2/5)", {},
                              "0 = same as youngs_modulus"},
                             0.0, Range::closed(0.0, 1e13)};
  } material;

  // [[materials]]: named materials (dem/material.hpp), chosen per particle by particles.material,
  // agglomerate.material, the structure file's material column, projectile.material and wall.material.
  struct Materials {
    Table t{"materials", kAgglomerateCommands, "named materials, each chosen by its name (the [material] table is \"default\")",
            true};
    Text name{t, {"materials.name", "", "name of the material (not default, same or rigid; unique)"}, std::nullopt};
    Real density{t, {"materials.density", "kg/m^3", "density rho", "the [material] value"}, std::nullopt,
                 Range::open_closed(0.0, 1e5)};
    Real youngs_modulus{t, {"materials.youngs_modulus", "Pa", "Young's modulus E", "the [material] value"},
                        std::nullopt, Range::open_closed(0.0, 1e13)};
    Real poisson_ratio{t, {"materials.poisson_ratio", "", "Poisson ratio nu", "the [material] value"}, std::nullopt,
                       Range::open(-1.0, 0.5)};
    Real surface_energy{t, {"materials.surface_energy", "J/m^2", "surface energy gamma", "the [material] value"},
                        std::nullopt, Range::open_closed(0.0, 100.0)};
    Real restitution{t, {"materials.restitution", "", "coefficient of restitution e", "the [material] value"},
                     std::nullopt, Range::open_closed(0.0, 1.0)};
    Real friction{t, {"materials.friction", "", "sliding friction coefficient mu_F", "the [material] value"},
                  std::nullopt, Range::closed(0.0, 10.0)};
  } materials;

  // [contact] (the sub-models by name) is declared beside them: dem/contact/settings.hpp.

  struct Time {
    Table t{"time", kImpactCommands, "time stepping and run length"};
    Real dt{t, {"time.dt", "s", "time step, at most T0/10", {}, "0 = T0/steps_per_period"}, 0.0, Range::nonnegative()};
    Real steps_per_period{t, {"time.steps_per_period", "", "steps per contact period T0 when dt = 0"}, 50.0,
                          Range::closed(10.0, 1e6)};
    Real after_contact{t, {"time.after_contact", "s", "run time after the first projectile contact"}, 2e-3,
                       Range::positive()};
    Real max_approach{t, {"time.max_approach", "s", "give up if no contact by then", {}, "0 = automatic"}, 0.0,
                      Range::nonnegative()};
    Real extension{t, {"time.extension", "s", "extra run time while the outcome is undecided"}, 1e-3,
                   Range::positive()};
    Integer max_extensions{t, {"time.max_extensions", "", "most extensions of an undecided run"}, 4, 0, 100};
    Real relax_time{t, {"time.relax_time", "s", "longest relaxation of a charged agglomerate before launch"}, 1e-3,
                    Range::nonnegative()};
    Real relax_energy{t, {"time.relax_energy", "F_C delta_C", "relaxed once the kinetic energy is below this"},
                      1e-6, Range::positive()};
    Bool early_stop{t, {"time.early_stop", "", "stop once clearly broken (fragments escaping and far apart)"}, true};
    Real early_stop_gap{t, {"time.early_stop_gap", "r_p", "surface gap of escaping fragments for an early stop"},
                        2.0, Range::positive()};
    // Read only when set (cases without it resolve as before).
    Choice intact_stop{t,
                       {"time.intact_stop", "",
                        "stop a run once it provably can no longer break (an energy bound below half the energy to "
                        "break a contact; impact/intact.hpp, docs/model.md A.3): vcrit = in "
                        "break-up bisections (vcrit, calibrate), on = in every run (it decides break-up, not "
                        "sticking), off = never",
                        "vcrit"},
                       std::nullopt, {"vcrit", "on", "off"}};
  } time;

  struct Agglomerate {
    Table t{"agglomerate", kAgglomerateCommands, "the target agglomerate"};
    Choice shape{t,
                 {"agglomerate.shape", "",
                  "built-in shape; list = the [[particles]] entries; fractal = tunable fractal aggregate (PCA then "
                  "CCA on N = k_f (R_g/a)^D_f); bpca / bcca = ballistic particle-cluster / cluster-cluster "
                  "aggregate; file = the primaries of agglomerate.file (docs/model.md, structure builder)"},
                 "tetrahedron", {"tetrahedron", "square", "list", "fractal", "bpca", "bcca", "file"}};
    Real radius{t,
                {"agglomerate.radius", "m",
                 "particle radius r_p of the built-in shapes; geometric-mean primary radius a_g of fractal, bpca, bcca"},
                10e-6, Range::open_closed(0.0, 0.1)};
    // The keys of the generated shapes are read only with those shapes (the resolved config of the
    // other shapes stays as it was).
    BuilderKeys builder{t, "agglomerate", "agglomerate"};
    const Integer& seed = builder.seed;
    const Integer& primaries = builder.primaries;
    const Real& fractal_dimension = builder.fractal_dimension;
    const Real& fractal_prefactor = builder.fractal_prefactor;
    const Real& radius_std = builder.radius_std;
    const Text& file = builder.file;
    Bool charged{t, {"agglomerate.charged", "", "alternate +/- charge_density on the built-in shapes"}, false};
    Real charge_density{t, {"agglomerate.charge_density", "C/m^2", "surface charge density |sigma_f|"}, 10e-6,
                        Range::closed(0.0, 1e-2)};
    Real permittivity{t, {"agglomerate.permittivity", "", "relative permittivity kappa_p of the built-in shapes"},
                      1.0, Range::open_closed(0.0, 1e6)};
    Text material{t,
                  {"agglomerate.material", "",
                   "material of every primary of the built-in and generated shapes, and of the file's primaries "
                   "without a material column: default or a [[materials]] name",
                   "default"},
                  std::nullopt};
    // Read only when set: absent, the resolved config stays as it was before the key existed.
    Choice orientation{t,
                       {"agglomerate.orientation", "",
                        "how the built-in shape faces the projectile (moving along +x, offset along y): "
                        "edge_across / edge_along = an edge (square: a side) faces it, normal to / along y; "
                        "face = a face (square: its plane) normal to x; vertex = a vertex (corner) points at it",
                        "the shape's original geometry: edge_across (tetrahedron), edge_along (square)"},
                       std::nullopt, {"edge_across", "edge_along", "face", "vertex"}};
  } agglomerate;

  struct Projectile {
    Table t{"projectile", kImpactCommands, "the incoming particle"};
    Real speed{t, {"projectile.speed", "m/s", "impact speed v_in"}, 0.18, Range::closed(0.0, 1e3)};
    Real offset_radii{t, {"projectile.offset_radii", "r_p", "lateral offset along y"}, 0.05, Range::closed(-10.0, 10.0)};
    Real gap_radii{t, {"projectile.gap_radii", "r_p", "initial surface gap"}, 1.0, Range::open_closed(0.0, 1e3)};
    Real radius{t, {"projectile.radius", "m", "projectile radius", "the agglomerate radius"}, std::nullopt,
                Range::open_closed(0.0, 0.1)};
    Real charge{t, {"projectile.charge", "C", "projectile charge"}, 0.0, Range::closed(-1e-3, 1e-3)};
    Real permittivity{t, {"projectile.permittivity", "", "relative permittivity kappa_p"}, 1.0, Range::open_closed(0.0, 1e6)};
    Text material{t, {"projectile.material", "", "material of the projectile: default or a [[materials]] name",
                                "the agglomerate's material"},
                  std::nullopt};
    // An aggregate projectile (read only when set, as the keys below): the builder's shapes and keys.
    Choice shape{t,
                 {"projectile.shape", "",
                  "sphere, or an aggregate of the structure builder as agglomerate.shape (fractal, bpca, bcca, file; "
                  "keys projectile.seed, primaries, ...; projectile.radius = its geometric-mean primary radius)",
                  "sphere"},
                 std::nullopt, {"sphere", "fractal", "bpca", "bcca", "file"}};
    BuilderKeys builder{t, "projectile", "projectile"};
    Choice orientation{t,
                       {"projectile.orientation", "",
                        "as_built, or random: an aggregate projectile turned about its centroid by a uniform random "
                        "rotation drawn from projectile.seed",
                        "as_built"},
                       std::nullopt, {"as_built", "random"}};
  } projectile;

  struct Output {
    Table t{"output", kImpactCommands, "output intervals"};
    Real timeseries_interval{t, {"output.timeseries_interval", "s", "interval of timeseries.csv rows"}, 5e-6,
                             Range::positive()};
    Real snapshot_interval{t, {"output.snapshot_interval", "s", "interval of VTK snapshots", {}, "0 = none"}, 1e-4,
                           Range::nonnegative()};
  } output;

  struct Vcrit {
    Table t{"vcrit", "vcrit, breakup", "critical break-up speed search"};
    Real v_min{t, {"vcrit.v_min", "m/s", "lowest speed of the scan"}, 0.02, Range::open_closed(0.0, 1e3)};
    Real v_max{t, {"vcrit.v_max", "m/s", "highest speed of the scan"}, 0.6, Range::open_closed(0.0, 1e3)};
    Integer scan_points{t, {"vcrit.scan_points", "", "speeds of the coarse linear scan"}, 12, 3, 1000};
    Real tolerance{t, {"vcrit.tolerance", "m/s", "bisection tolerance, at least 1e-9 v_max"}, 5e-4, Range::positive()};
    Integer points_per_round{t,
                             {"vcrit.points_per_round", "",
                              "speeds tried per bisection round; fixed by configuration so v_crit never depends "
                              "on the core count"},
                             2, 1, 64};
    // Read only when set (cases without it resolve as before).
    Choice criterion{t,
                     {"vcrit.criterion", "",
                      "what is bisected: breakup = the lowest speed from which every tested speed breaks the "
                      "agglomerate; sticking = the largest speed at which the agglomerate (wall.impact) or the "
                      "projectile stays (on the wall, on the target)",
                      "breakup"},
                     std::nullopt, {"breakup", "sticking"}};
    // Read only when set (cases without it resolve as before).
    Choice order{t,
                 {"vcrit.order", "",
                  "order of the runs of each batch: full = every speed of the scan and of each round; top_down = "
                  "from the highest speed down, stopping at the first without the event (same v_crit, bracket and "
                  "rounds; the runs below the bracket are skipped)",
                  "full"},
                 std::nullopt, {"full", "top_down"}};
  } vcrit;

  struct Breakup {
    Table t{"breakup", "breakup", "break-up probability against speed"};
    Reals speeds{t, {"breakup.speeds", "m/s", "impact speeds", "the vcrit scan grid (scan_points from v_min to v_max)"},
                 std::nullopt, Range::open_closed(0.0, 1e3)};
    Integer samples{t, {"breakup.samples", "", "runs per speed (offsets spread evenly)"}, 16, 1, 100000};
    Real offset_spread{t, {"breakup.offset_spread", "r_p", "half-width of the offset range"}, 0.05,
                       Range::closed(0.0, 10.0)};
    // Read only when set (as the orientation of the agglomerate).
    Integer orientations{t,
                         {"breakup.orientations", "",
                          "rigid rotations of the agglomerate, each run with every offset: a stratified covering of "
                          "all orientations (runs per speed = samples x orientations)",
                          "1 = only the configured orientation"},
                         std::nullopt, 1, 10000};
  } breakup;

  // [wall] (docs/dem.md "Gas and walls"; dem/wall.hpp). Read only when the section is present, so cases
  // without it resolve as before. [gas] of impact cases is the acoustic table (settings_acoustic.hpp).
  struct Wall {
    Table t{"wall", kImpactCommands, "a flat wall (JKR contact with an infinite partner)"};
    Bool enabled{t, {"wall.enabled", "", "the wall acts (false keeps the section but removes the wall)"}, true};
    Vector3 position{t, {"wall.position", "m", "a point of the wall plane"}, std::nullopt, Range::closed(-1e3, 1e3)};
    Vector3 normal{t, {"wall.normal", "", "normal of the wall, towards the particles (normalised)"}, Vec3{-1, 0, 0},
                   Range::closed(-1e6, 1e6)};
    Text material{t,
                  {"wall.material", "",
                   "same = each particle's own material, E* = E/(2(1-nu^2)); rigid = undeformable, E* = E/(1-nu^2); "
                   "default or a [[materials]] name = a wall of that material (pair rules of docs/model.md)"},
                  "same"};
    Bool impact{t,
                {"wall.impact", "",
                 "the agglomerate itself moves at projectile.speed along +x onto the wall; no projectile"},
                false};
    Bool grounded{t,
                  {"wall.grounded", "",
                   "grounded conducting wall: image charges of the charged and dielectric particles"},
                  false};
  } wall;

  std::vector<const Table*> tables() const;
};

const ImpactSettings& impact_settings();

}  // namespace agglo::settings
