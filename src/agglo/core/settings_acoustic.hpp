#pragma once
// Settings tables of the acoustic agglomeration command (acoustic, sweep): the one declaration of
// each key, its unit, default, range and meaning (docs/acoustics.md describes the model).
#include <cstdint>

#include "agglo/core/settings.hpp"

namespace agglo::settings {

inline constexpr std::string_view kAcousticCommands = "acoustic, sectional, sweep";

// Names of the outcome models of the DSMC, dry (solid-solid, outcomes.dry_model) and wet (solid-mixed,
// mixed-mixed, outcomes.wet_model) alike (acoustics/outcomes.hpp: the closed-form critical velocities, eq. 13
// dry and Ennis's eq. 14 wet; acoustics/outcome_table.hpp: a table of probabilities, one format for both).
inline constexpr std::string_view kOutcomeCriticalVelocity = "critical_velocity";
inline constexpr std::string_view kOutcomeTable = "table";

// Names of the aggregate structures of a DSMC population and of its mobility-radius rules
// (acoustics/structure.hpp: the formulas, units and sources).
inline constexpr std::string_view kStructureCompact = "compact";
inline constexpr std::string_view kStructureFractal = "fractal";
inline constexpr std::string_view kMobilityCollision = "collision";
inline constexpr std::string_view kFractalLawGiven = "given";  // population.fractal_law
inline constexpr std::string_view kFractalLawTable = "table";
inline constexpr std::string_view kMobilitySorensen = "sorensen";

struct AcousticSettings {
  struct Top {
    Table t{"", kAcousticCommands, "top-level keys of an acoustic case"};
    Integer seed{t, {"seed", "", "random seed of the sampling and the collisions"}, 1, 0, INT64_MAX};
  } top;

  struct Gas {
    // Also read by the impact commands when an impact case has a [gas] section (drag on every
    // particle, docs/dem.md "Gas and walls"); flow and drag are theirs only.
    Table t{"gas", "acoustic, sectional, sweep, collide, vcrit, breakup, outcomes", "carrier gas (air)"};
    Real temperature{t, {"gas.temperature", "K", "gas temperature"}, 298.15, Range::open_closed(0.0, 1e4)};
    Real pressure{t, {"gas.pressure", "Pa", "gas pressure"}, 101325.0, Range::open_closed(0.0, 1e9)};
    Bool gravity{t, {"gas.gravity", "", "gravitational settling"}, true};
    Real viscosity{t, {"gas.viscosity", "Pa s", "dynamic viscosity", "Sutherland's law at the temperature"},
                   std::nullopt, Range::open_closed(0.0, 1.0)};
    Real mean_free_path{t, {"gas.mean_free_path", "m", "mean free path", "from viscosity, density and mean speed"},
                        std::nullopt, Range::open_closed(0.0, 1.0)};
    Bool drag{t, {"gas.drag", "", "impact cases: slip-corrected Stokes drag on every particle"}, true};
    Vector3 flow{t, {"gas.flow", "m/s", "impact cases: uniform gas velocity u of the drag"}, Vec3{0, 0, 0},
                 Range::closed(-1e3, 1e3)};
  } gas;

  struct Sound {
    Table t{"sound", kAcousticCommands, "travelling sound wave"};
    Bool enabled{t, {"sound.enabled", "", "sound field on"}, true};
    Real level_db{t, {"sound.level_db", "dB", "sound pressure level L"}, 140.0, Range::any()};
    Real frequency_hz{t, {"sound.frequency_hz", "Hz", "frequency f"}, 2000.0, Range::open_closed(0.0, 1e9)};
  } sound;

  struct Time {
    Table t{"time", kAcousticCommands, "time stepping"};
    Real end{t, {"time.end", "s", "simulated time (a whole number of collision steps)"}, std::nullopt,
             Range::positive()};
    Real collision_dt{t, {"time.collision_dt", "s", "collision (DSMC) step"}, 1e-5, Range::positive()};
    Real motion_dt{t, {"time.motion_dt", "s", "particle motion step (divides the collision step)", "the collision step"},
                   std::nullopt, Range::positive()};
    Choice integrator{t, {"time.integrator", "", "particle motion integrator"}, "exact", {"exact", "explicit", "none"}};
    Choice initial_velocity{t, {"time.initial_velocity", "", "initial particle velocity"}, "steady",
                            {"steady", "gas", "rest"}};
    Choice selection{t,
                     {"time.selection", "", "collision-pair selection: binned majorants, or Zhao et al.'s modified Nanbu",
                      "\"binned\" without motion (time.integrator = \"none\"), else \"nanbu\""},
                     std::nullopt, {"nanbu", "binned"}};
    Choice nanbu_guard{t, {"time.nanbu_guard", "", "when P_ij > 1/N: sub-cycle the cell, or stop"}, "subcycle",
                       {"subcycle", "strict"}};
    Integer max_subcycles{t, {"time.max_subcycles", "", "most sub-cycles of one cell and step"}, 100000, 1,
                          1000000000};
  } time;

  struct Population {
    Table t{"population", kAcousticCommands, "sampled particle populations (at least one)", true};
    Text name{t, {"population.name", "", "population name"}, std::nullopt};
    Choice phase{t, {"population.phase", "", "solid particles or liquid droplets"}, std::nullopt, {"solid", "liquid"}};
    Choice distribution{t, {"population.distribution", "", "size distribution"}, std::nullopt,
                        {"lognormal", "monodisperse", "exponential", "table"}};
    Real number_concentration{t, {"population.number_concentration", "1/m^3", "number concentration N_tot"},
                              std::nullopt, Range::closed(0.0, 1e22)};
    Real density{t, {"population.density", "kg/m^3", "particle density", "2500 (solid), 1000 (liquid)"},
                 std::nullopt, Range::open_closed(0.0, 1e5)};
    Integer samples{t, {"population.samples", "", "computational samples"}, std::nullopt, 1, 100000000};
    Choice weight_rounding{t, {"population.weight_rounding", "", "integer weights: round each, or conserve the sum"},
                           "nearest", {"nearest", "conserving"}};
    Real geometric_mean_diameter{t, {"population.geometric_mean_diameter", "m", "lognormal: d_g"}, std::nullopt,
                                 Range::open_closed(0.0, 1e-2)};
    Real geometric_std{t, {"population.geometric_std", "", "lognormal: sigma_g"}, std::nullopt,
                       Range::closed(1.0, 1e3)};
    Integer bins{t, {"population.bins", "", "lognormal: size bins"}, 40, 1, 100000};
    Real lognormal_range{t, {"population.lognormal_range", "", "lognormal: sampled ln d within +- this many ln sigma_g "
                                                             "of ln d_g (3.5 leaves out 7.7 % of the volume at sigma_g = 2)"},
                         3.5, Range::closed(1.0, 8.0)};
    Choice lognormal_weights{t, {"population.lognormal_weights", "",
                                 "lognormal: equal samples per size bin weighted by the bin's probability (by_bin), "
                                 "or equal weights at stratified quantiles of the whole range (equal, as PartMC)"},
                             "by_bin", {"by_bin", "equal"}};
    Real diameter{t, {"population.diameter", "m", "monodisperse: diameter"}, std::nullopt, Range::closed(0.0, 1e-2)};
    Real mean_volume{t, {"population.mean_volume", "m^3", "exponential: mean volume v0"}, std::nullopt,
                     Range::open_closed(0.0, 1e-6)};
    Reals table_diameters{t, {"population.table_diameters", "m", "table: diameters"}, std::nullopt,
                          Range::open_closed(0.0, 1e-2)};
    Reals table_fractions{t, {"population.table_fractions", "", "table: number fractions"}, std::nullopt,
                          Range::nonnegative()};
    // Aggregate structure (acoustics/structure.hpp); every key is read only when set, so that the resolved
    // config of a compact case stays as it was.
    Choice structure{t,
                     {"population.structure", "",
                      "solid particles as compact spheres of their volume, or fractal aggregates of primaries "
                      "(collision radius r_p (n_p/k_f)^(1/D_f))",
                      "compact (absent: read only when set)"},
                     std::nullopt, {kStructureCompact, kStructureFractal}};
    Real primary_radius{t, {"population.primary_radius", "m", "structure = \"fractal\": primary radius r_p"},
                        std::nullopt, Range::open_closed(0.0, 1e-3)};
    Real fractal_dimension{t, {"population.fractal_dimension", "", "structure = \"fractal\": fractal dimension D_f"},
                           std::nullopt, Range::open_closed(1.0, 3.0)};
    Real fractal_prefactor{t, {"population.fractal_prefactor", "", "structure = \"fractal\": fractal prefactor k_f"},
                           std::nullopt, Range::open_closed(0.0, 100.0)};
    Choice fractal_law{t,
                       {"population.fractal_law", "",
                        "structure = \"fractal\": D_f and k_f given by fractal_dimension and fractal_prefactor, or "
                        "taken from the dry outcome table's structures (its attributes fractal_dimension, "
                        "fractal_prefactor)",
                        "given (absent: read only when set)"},
                       std::nullopt, {kFractalLawGiven, kFractalLawTable}};
    Choice mobility_radius{t,
                           {"population.mobility_radius", "",
                            "structure = \"fractal\": drag (mobility) radius: the collision radius, or "
                            "Sorensen's (2011) continuum r_p n_p^0.46",
                            "collision (absent: read only when set)"},
                           std::nullopt, {kMobilityCollision, kMobilitySorensen}};
    // Charge and permittivity (docs/acoustics.md §1.7): read only when set; they enter only the lookup of a
    // dry outcome table with charge / permittivity axes (acoustics/outcome_table.hpp).
    Real charge_density{t,
                        {"population.charge_density", "C/m^2",
                         "surface charge density sigma of every particle at t = 0 (signed): charge sigma pi d^2, d "
                         "the volume-equivalent diameter; summed on merging, shared by mass on breaking",
                         "uncharged (absent: read only when set)"},
                        std::nullopt, Range::closed(-1e-2, 1e-2)};
    Real permittivity{t,
                      {"population.permittivity", "",
                       "relative permittivity kappa_p of the particles (an outcome table's permittivity axis)",
                       "1 (absent: read only when set)"},
                      std::nullopt, Range::open_closed(0.0, 1e6)};
  } population;

  struct Sampling {
    Table t{"sampling", kAcousticCommands, "how the samples are spread over the cells at t = 0"};
    Choice placement{t, {"sampling.placement", "",
                         "stratified: every population's samples spread evenly over the cells; random: uniform "
                         "in the box (Zhao et al.'s method)"},
                     "stratified", {"stratified", "random"}};
    Integer min_samples_per_cell{t, {"sampling.min_samples_per_cell", "",
                                     "a population with fewer samples per cell is split into clones of lower "
                                     "weight at t = 0 (0 = never; Zhao et al.'s method)"},
                                 16, 0, 1000000};
  } sampling;

  struct Domain {
    Table t{"domain", kAcousticCommands, "periodic box and cells"};
    Real length_x{t, {"domain.length_x", "m", "length along the wave", "one wavelength c/f (required without sound)"},
                  std::nullopt, Range::open_closed(0.0, 1e3)};
    Real length_y{t, {"domain.length_y", "m", "transverse length"}, 0.01, Range::open_closed(0.0, 1e3)};
    Real length_z{t, {"domain.length_z", "m", "transverse length"}, 0.01, Range::open_closed(0.0, 1e3)};
    Integer cells_x{t, {"domain.cells_x", "", "cells along x"}, 100, 1, 100000000};
    Integer cells_y{t, {"domain.cells_y", "", "cells along y"}, 1, 1, 100000000};
    Integer cells_z{t, {"domain.cells_z", "", "cells along z"}, 1, 1, 100000000};
    Integer min_cells_per_wavelength{t, {"domain.min_cells_per_wavelength", "", "cells must resolve the wave"}, 100,
                                     1, 100000000};
  } domain;

  // [kernels] (the mechanisms by name) is declared beside them: acoustics/kernels/keys.hpp.

  struct Outcomes {
    Table t{"outcomes", kAcousticCommands, "collision outcomes (coalescence or rebound)"};
    Bool always_coalesce{t, {"outcomes.always_coalesce", "", "every collision coalesces (kernel tests)"}, false};
    Real hamaker{t, {"outcomes.hamaker", "J", "Hamaker constant A"}, 1e-19, Range::open_closed(0.0, 1e-16)};
    Real contact_distance{t, {"outcomes.contact_distance", "m", "minimum contact distance z0"}, 4e-10,
                          Range::open_closed(0.0, 1e-6)};
    Real contact_pressure{t, {"outcomes.contact_pressure", "Pa", "contact pressure p_c"}, 3e8, Range::open_closed(0.0, 1e12)};
    Real restitution{t, {"outcomes.restitution", "", "restitution coefficient e"}, 0.6, Range::open_closed(0.0, 1.0)};
    Real friction{t, {"outcomes.friction", "", "friction coefficient f_p"}, 0.2, Range::closed(0.0, 10.0)};
    Real liquid_viscosity{t, {"outcomes.liquid_viscosity", "Pa s", "liquid viscosity mu_l"}, 8.9e-4,
                          Range::open_closed(0.0, 1e3)};
    Real film_roughness_ratio{t, {"outcomes.film_roughness_ratio", "", "liquid film to roughness ratio delta/h_a"},
                              10.0, Range::open(1.0, 1e300)};
    Real solid_density{t, {"outcomes.solid_density", "kg/m^3", "rho_s of the wet outcome model"}, 2500.0,
                       Range::open_closed(0.0, 1e5)};
    Bool energy_compensation{t, {"outcomes.energy_compensation", "", "kinetic energy compensation of merges"}, true};
    Choice dry_model{t,
                     {"outcomes.dry_model", "",
                      "outcome of solid-solid collisions: the closed-form critical velocity (eq. 13), or drawn "
                      "from a table of P_stick, P_bounce, P_break (outcomes.table)",
                      "critical_velocity (absent: read only when set)"},
                     std::nullopt, {kOutcomeCriticalVelocity, kOutcomeTable}};
    Text table{t, {"outcomes.table", "", "dry_model = \"table\": NetCDF outcome table (docs/acoustics.md, written by "
                                         "agglo outcomes), relative to the case file"},
               std::nullopt};
    Choice wet_model{t,
                     {"outcomes.wet_model", "",
                      "outcome of solid-mixed and mixed-mixed collisions: the closed-form Ennis critical velocity "
                      "(eq. 14), or drawn from a table of P_stick, P_bounce, P_break (outcomes.wet_table)",
                      "critical_velocity (absent: read only when set)"},
                     std::nullopt, {kOutcomeCriticalVelocity, kOutcomeTable}};
    Text wet_table{t, {"outcomes.wet_table", "", "wet_model = \"table\": NetCDF outcome table of wet pairs (format "
                                                 "of outcomes.table), relative to the case file"},
                   std::nullopt};
  } outcomes;

  struct Output {
    Table t{"output", kAcousticCommands, "outputs"};
    Reals psd_times{t, {"output.psd_times", "s", "times of psd.csv, within the run", "0, t/4, t/2, 3t/4, t (t = run end)"},
                    std::nullopt, Range::nonnegative()};
    Integer psd_bins{t, {"output.psd_bins", "", "size bins of psd.csv"}, 60, 1, 100000};
    Real psd_d_min{t, {"output.psd_d_min", "m", "smallest diameter of psd.csv"}, 1e-8, Range::open_closed(0.0, 1.0)};
    Real psd_d_max{t, {"output.psd_d_max", "m", "largest diameter of psd.csv"}, 1e-4, Range::open_closed(0.0, 1.0)};
    Real efficiency_interval{t, {"output.efficiency_interval", "s", "interval of efficiency.csv rows", "run end / 200"},
                             std::nullopt, Range::positive()};
    Reals snapshot_times{t, {"output.snapshot_times", "s", "times of snapshots.csv, within the run", "0, t/8, t/4, t/2 (t = run end)"},
                         std::nullopt, Range::nonnegative()};
    Real snapshot_x_fraction{t, {"output.snapshot_x_fraction", "", "snapshots keep 0 <= x <= fraction * length_x"},
                             0.25, Range::open_closed(0.0, 1.0)};
    Bool plots{t, {"output.plots", "", "make PNG plots"}, true};
  } output;

  struct Sectional {
    Table t{"sectional", "sectional", "deterministic sectional solver (fixed pivot); read by agglo sectional only"};
    Integer bins_per_decade{t, {"sectional.bins_per_decade", "", "pivots per decade of diameter"}, 40, 4, 10000};
    Real d_min{t, {"sectional.d_min", "m", "diameter of the smallest pivot"}, 1e-9, Range::positive()};
    Real d_max{t, {"sectional.d_max", "m", "diameter of the largest pivot"}, 1e-3, Range::positive()};
    Real tolerance{t, {"sectional.tolerance", "", "local error per time step, relative to N and to the volume"}, 1e-6,
                   Range::open_closed(0.0, 0.1)};
  } sectional;

  std::vector<const Table*> tables() const;
};

const AcousticSettings& acoustic_settings();

}  // namespace agglo::settings
