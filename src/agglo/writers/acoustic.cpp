#include "agglo/writers/acoustic.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "agglo/io/dataset_scalars.hpp"

namespace agglo::writers {

using io::ints_of;
using io::reals_of;

namespace {
constexpr double kPerCm3 = 1e-6;  // 1/m^3 -> 1/cm^3
using acoustics::AcousticObservations;

// The collision counters of result.json: the keys both selections share, then the meaning each
// selection gives to the trial, bound and subdivision counters (binned: candidates against the row
// majorant; Nanbu: trials against the per-step bound P_n).
nlohmann::json stats_json(const acoustics::CollisionStats& s, acoustics::Selection sel, bool dry_table,
                          bool wet_table) {
  const auto by_kind = [](const auto& c) { return nlohmann::json{{"droplet", c[0]}, {"dry", c[1]}, {"wet", c[2]}}; };
  nlohmann::json j{{"particle_steps", s.particle_steps},     {"kernel_evals", s.kernel_evals},
                   {"collisions", s.collisions},             {"coalescences", by_kind(s.coalescences)},
                   {"rebounds", by_kind(s.rebounds)},        {"violations", s.violations},
                   {"refills", s.refills},                   {"dead_samples", s.dead},
                   {"energy_lost_J", s.energy_lost},         {"energy_returned_J", s.energy_returned}};
  const bool binned = sel == acoustics::Selection::binned;
  j[binned ? "candidates" : "trials"] = s.trials;
  j[binned ? "max_beta_over_majorant" : "max_pn_evaluated"] = s.max_pn;
  j[binned ? "cell_steps_subdivided" : "subcycled_particle_steps"] = s.subcycled;
  j[binned ? "max_substeps" : "max_subcycles"] = s.max_subcycles;
  if (binned) j["full_row_rate_computations"] = s.row_rate_updates;
  else j["max_bound_pn"] = s.max_bound_pn;
  if (dry_table) {  // outcomes.dry_model = "table" only, so the default outputs keep their keys
    j["outcome_table_queries"] = s.table_queries;
    j["outcome_table_clamped"] = s.table_clamped;
  }
  if (wet_table) {  // outcomes.wet_model = "table" only
    j["wet_outcome_table_queries"] = s.wet_table_queries;
    j["wet_outcome_table_clamped"] = s.wet_table_clamped;
  }
  return j;
}

// psd.csv's bins: lower and upper edges and centres (geometric mean of the edges) [m].
struct Bins {
  std::vector<double> lo, hi, mid;
};
Bins bins_of(const std::vector<double>& e) {
  Bins b;
  for (std::size_t k = 0; k + 1 < e.size(); ++k) {
    b.lo.push_back(e[k]);
    b.hi.push_back(e[k + 1]);
    b.mid.push_back(std::sqrt(e[k] * e[k + 1]));
  }
  return b;
}

// Name of a PM column: pm2_5_vol_ug_m3, pm2_5_aero_reduction, ...
std::string pm_column(std::size_t k, bool aero, const char* what) {
  return fmt::format("{}_{}_{}", acoustics::kPmNames[k], aero ? "aero" : "vol", what);
}

// PM1, PM2.5, PM10 mass concentrations by volume-equivalent and by aerodynamic diameter (diagnostics.hpp)
// and the fraction of each removed since the first row (t = 0).
void add_pm_columns(io::Table& t, const std::vector<acoustics::EfficiencyRow>& e) {
  using R = acoustics::EfficiencyRow;
  for (const bool aero : {false, true}) {
    const char* diameter = aero ? "aerodynamic diameter" : "volume-equivalent diameter";
    const auto of = [aero](const R& r) -> const std::array<double, 3>& { return aero ? r.pm.aerodynamic : r.pm.volume; };
    for (std::size_t k = 0; k < 3; ++k)
      t.real(pm_column(k, aero, "ug_m3"), "ug m-3",
             fmt::format("{} mass concentration ({} < {:g} um)", acoustics::kPmLabels[k], diameter,
                         acoustics::kPmCuts[k] * 1e6),
             reals_of(e, [&](const R& r) { return of(r)[k] * acoustics::kMicrogramsPerKg; }));
    for (std::size_t k = 0; k < 3; ++k)
      t.real(pm_column(k, aero, "reduction"), "1",
             fmt::format("fraction of the {} mass ({}) removed since t = 0", acoustics::kPmLabels[k], diameter),
             reals_of(e, [&](const R& r) { return acoustics::pm_reduction(of(e.front())[k], of(r)[k]); }));
  }
}

io::Table efficiency_table(const AcousticObservations& o) {
  using R = acoustics::EfficiencyRow;
  const auto& e = o.efficiency;
  io::Table t("efficiency.csv", {{"time", e.size()}}, "{:.8g}");
  t.real("time", "s", "simulated time (efficiency.csv t_s)", reals_of(e, [](const R& r) { return r.t; })).header({"t_s"});
  t.real("n_total_cm3", "cm-3", "number concentration, all particles",
         reals_of(e, [](const R& r) { return r.counts.n_total * kPerCm3; }));
  for (std::size_t k = 0; k < 3; ++k) {
    const std::string phase = acoustics::phase_name(static_cast<acoustics::Phase>(k));
    t.real("n_" + phase + "_cm3", "cm-3", "number concentration, " + phase,
           reals_of(e, [k](const R& r) { return r.counts.n_phase[k] * kPerCm3; }));
  }
  t.real("fine_efficiency", "1", "agglomeration efficiency of the fine particles",
         reals_of(e, [](const R& r) { return r.fine_efficiency; }));
  t.real("pure_droplet_fraction", "1", "fraction of droplets still free of solid",
         reals_of(e, [](const R& r) { return r.pure_droplet_fraction; }));
  t.real("solid_volume_fraction", "1", "solid volume per box volume",
         reals_of(e, [](const R& r) { return r.counts.solid_volume; }))
      .with_format("{:.17g}");
  t.real("liquid_volume_fraction", "1", "liquid volume per box volume",
         reals_of(e, [](const R& r) { return r.counts.liquid_volume; }))
      .with_format("{:.17g}");
  t.integer("collisions", "1", "collisions so far", ints_of(e, [](const R& r) { return r.collisions; }));
  t.integer("subcycled_particle_steps", "1", "subcycled particle steps so far",
            ints_of(e, [](const R& r) { return r.subcycled; }));
  if (o.dsmc) add_pm_columns(t, e);
  return t;
}

// Collisions that stuck, bounced and broke by pair type over the whole run (DSMC only).
io::Table outcomes_by_pair_table(const acoustics::CollisionStats& s) {
  io::Table t("outcomes_by_pair.csv", {{"pair_type", 3}}, "{:.6g}");
  t.flag("pair_type", "colliding pair: droplet (with a pure droplet), dry (solid-solid), wet (solid-mixed, mixed-mixed)",
         {acoustics::kPairTypeNames.begin(), acoustics::kPairTypeNames.end()}, {0, 1, 2});
  const std::array<const std::uint64_t*, 3> counts = {s.coalescences, s.rebounds, s.breakups};
  std::vector<std::int64_t> n(3, 0);
  for (const auto* c : counts)
    for (std::size_t k = 0; k < 3; ++k) n[k] += static_cast<std::int64_t>(c[k]);
  t.integer("pair_collisions", "1", "collisions of the pair type over the run", n);
  const std::array<const char*, 3> what = {"stuck", "bounced", "broke"};
  const std::array<const char*, 3> meaning = {"stuck (coalesced)", "bounced (rebound)",
                                              "broke into fragments (dry pairs with an outcome table)"};
  for (std::size_t m = 0; m < 3; ++m)
    t.integer(what[m], "1", std::string("collisions of the pair type that ") + meaning[m],
              {counts[m], counts[m] + 3});
  for (std::size_t m = 0; m < 3; ++m) {
    std::vector<double> f;
    for (std::size_t k = 0; k < 3; ++k)
      f.push_back(n[k] > 0 ? static_cast<double>(counts[m][k]) / static_cast<double>(n[k]) : 0.0);
    t.real(std::string(what[m]) + "_fraction", "1",
           std::string("fraction of the pair type's collisions that ") + meaning[m] + " (0: no collisions)", f);
  }
  return t;
}

io::Table psd_table(const AcousticObservations& o) {
  const auto& e = o.bins.edges;
  const Bins b = bins_of(e);
  io::Table t("psd.csv", {{"psd_time", o.psd.size()}, {"diameter", b.mid.size()}}, "{:.6g}");
  t.add_dim("diameter_edge", e.size());
  t.real("psd_time", "s", "time of the size distribution", reals_of(o.psd, [](const auto& r) { return r.t; }))
      .over({"psd_time"})
      .header({"t_s"})
      .with_format("{:.8g}");
  t.real("d_lo_m", "m", "lower bin edge", b.lo).over({"diameter"});
  t.real("d_hi_m", "m", "upper bin edge", b.hi).over({"diameter"});
  t.real("diameter", "m", "bin centre diameter (geometric mean of the edges, psd.csv d_mid_m)", b.mid)
      .over({"diameter"})
      .header({"d_mid_m"});
  t.real("diameter_edge", "m", "bin edge diameters", e).over({"diameter_edge"}).header({});
  const char* names[4] = {"solid", "liquid", "mixed", "total"};
  for (std::size_t p = 0; p < 4; ++p) {
    std::vector<double> v;
    for (const auto& rec : o.psd)
      for (std::size_t k = 0; k < b.mid.size(); ++k) v.push_back(rec.dndlogd[p][k] * kPerCm3);
    t.real(std::string(names[p]) + "_dNdlogd_cm3", "cm-3", std::string("size distribution dN/dlog10(d), ") + names[p],
           v);
  }
  return t;
}

io::Table snapshot_table(const AcousticObservations& o) {
  using S = acoustics::SnapshotRow;
  const auto& s = o.snapshots;
  io::Table t("snapshots.csv", {{"snapshot_row", s.size()}}, "{:.8g}");
  t.real("snapshot_time", "s", "time of the snapshot (snapshots.csv t_s)", reals_of(s, [](const S& r) { return r.t; }))
      .header({"t_s"});
  t.integer("id", "1", "sample id", ints_of(s, [](const S& r) { return r.id; }));
  t.real("x_m", "m", "sample position x", reals_of(s, [](const S& r) { return r.x; }));
  t.real("y_m", "m", "sample position y", reals_of(s, [](const S& r) { return r.y; }));
  t.real("z_m", "m", "sample position z", reals_of(s, [](const S& r) { return r.z; }));
  t.real("d_m", "m", "sample diameter", reals_of(s, [](const S& r) { return r.d; })).with_format("{:.6g}");
  t.real("solid_volume_m3", "m3", "solid volume of the particle", reals_of(s, [](const S& r) { return r.vol_s; }))
      .with_format("{:.6g}");
  t.real("liquid_volume_m3", "m3", "liquid volume of the particle", reals_of(s, [](const S& r) { return r.vol_l; }))
      .with_format("{:.6g}");
  t.real("weight", "1", "statistical weight (particles per sample)", reals_of(s, [](const S& r) { return r.w; }))
      .with_format("{:g}");
  std::vector<std::string> phases;
  for (int k = 0; k < 3; ++k) phases.emplace_back(acoustics::phase_name(static_cast<acoustics::Phase>(k)));
  t.flag("phase", "phase of the particle", phases, ints_of(s, [](const S& r) { return static_cast<int>(r.phase); }));
  return t;
}

double rel_change(double a, double b) { return a > 0 ? b / a - 1 : 0.0; }

// The PM columns' last values under the columns' names (results.nc keeps the series only).
void add_pm_summary(nlohmann::json& j, const std::vector<acoustics::EfficiencyRow>& e) {
  const auto &a = e.front().pm, &b = e.back().pm;
  for (const bool aero : {false, true})
    for (std::size_t k = 0; k < 3; ++k) {
      const double m0 = aero ? a.aerodynamic[k] : a.volume[k], m1 = aero ? b.aerodynamic[k] : b.volume[k];
      j[pm_column(k, aero, "ug_m3")] = m1 * acoustics::kMicrogramsPerKg;
      j[pm_column(k, aero, "reduction")] = acoustics::pm_reduction(m0, m1);
    }
}

// The scalars of both the DSMC and the sectional run.
nlohmann::json common_summary(const AcousticObservations& o) {
  const auto& last = o.efficiency.back();
  const auto &c0 = o.initial, &c1 = o.final;
  return {{"fine_efficiency", last.fine_efficiency},
          {"pure_droplet_fraction", last.pure_droplet_fraction},
          {"last_time_with_pure_droplets_s", o.last_time_with_pure_droplets},
          {"n_solid_initial_cm3", c0.n_phase[0] * kPerCm3},
          {"n_solid_final_cm3", c1.n_phase[0] * kPerCm3},
          {"n_total_initial_cm3", c0.n_total * kPerCm3},
          {"n_total_final_cm3", c1.n_total * kPerCm3},
          {"samples", o.samples},
          {"steps", o.steps},
          {"u_amp_m_s", o.u_amp},
          {"solid_volume_rel_change", rel_change(c0.solid_volume, c1.solid_volume)},
          {"liquid_volume_rel_change", rel_change(c0.liquid_volume, c1.liquid_volume)},
          {o.selection == acoustics::Selection::binned ? "binned" : "nanbu", 
           stats_json(o.stats, o.selection, o.dry_table, o.wet_table)},
          {"wall_time_s", o.wall_time_s}};
}
}  // namespace

nlohmann::json acoustic_summary(const AcousticObservations& o) {
  nlohmann::json j = common_summary(o);
  if (o.dsmc) add_pm_summary(j, o.efficiency);
  return j;
}

std::vector<io::Table> acoustic_tables(const AcousticObservations& o) {
  std::vector<io::Table> t;
  t.push_back(efficiency_table(o));
  t.push_back(psd_table(o));
  t.push_back(snapshot_table(o));
  if (o.dsmc) t.push_back(outcomes_by_pair_table(o.stats));
  return t;
}

void write_acoustic(const OutputDir& out, const AcousticObservations& o, bool tables) {
  if (tables)
    for (const auto& t : acoustic_tables(o)) io::write_csv(out, t);
  out.write_text("run.log", o.log);
  if (tables) out.write_json("summary.json", acoustic_summary(o));
}

io::Dataset acoustic_dataset(const AcousticObservations& o) {
  io::Dataset d;
  for (const auto& t : acoustic_tables(o)) t.add_to(d);
  if (!o.efficiency.empty()) io::add_scalars(d, acoustic_summary(o));  // the series' last values are already there
  return d;
}

}  // namespace agglo::writers
