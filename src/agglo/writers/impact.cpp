#include "agglo/writers/impact.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "agglo/impact/orientation_set.hpp"
#include "agglo/io/dataset_scalars.hpp"
#include "agglo/io/vtk.hpp"

namespace agglo::writers {

using io::VtkArray;
using io::vtk_vectors;

io::Table timeseries_table(const Recorder& rec) {
  using Row = impact::TimeseriesRow;
  const auto& rows = rec.rows;
  io::Table t("timeseries.csv", {{"time", rows.size()}}, "{:.9e}");
  t.real("time", "s", "time since launch", io::reals_of(rows, [](const Row& r) { return r.t; })).header({"t"});
  t.real("kinetic_energy", "J", "kinetic energy of all particles", io::reals_of(rows, [](const Row& r) { return r.kinetic; }));
  t.real("electrostatic_energy", "J", "electrostatic energy",
         io::reals_of(rows, [](const Row& r) { return r.electrostatic; }));
  t.real("U_over_U0", "1", "electrostatic energy over U0 = 2 pi r_p^3 sigma_f^2 / eps0",
         io::reals_of(rows, [](const Row& r) { return r.u_over_u0; }));
  t.real("radius_of_gyration", "m", "radius of gyration of all particles",
         io::reals_of(rows, [](const Row& r) { return r.rg; }));
  t.integer("n_contacts", "1", "number of contacts", io::ints_of(rows, [](const Row& r) { return r.contacts; }));
  t.real("radius_of_gyration_agglomerate", "m", "radius of gyration of the original agglomerate particles",
         io::reals_of(rows, [](const Row& r) { return r.rg_agglomerate; }));
  return t;
}

void write_timeseries(const OutputDir& out, const Recorder& rec) { io::write_csv(out, timeseries_table(rec)); }

namespace {
// The snapshots of an earlier run into the same folder (particles.pvd, snapshots/particles_*.vtp), so
// that a new run with fewer or no snapshots does not leave them beside its own.
void remove_old_snapshots(const OutputDir& out) {
  std::error_code ec;
  std::filesystem::remove(out.file("particles.pvd"), ec);
  for (const auto& e : std::filesystem::directory_iterator(out.file("snapshots"), ec)) {
    const auto name = e.path().filename().string();
    if (name.rfind("particles_", 0) == 0 && e.path().extension() == ".vtp") std::filesystem::remove(e.path(), ec);
  }
}

// One snapshot's particles as VTK point data (the active scalars: radius).
std::vector<VtkArray> point_data(const dem::ParticleSnapshot& s) {
  return {{"radius", "Float64", 1, s.radius},
          vtk_vectors("velocity", s.velocity),
          vtk_vectors("angular_velocity", s.angular_velocity),
          {"charge", "Float64", 1, s.charge},
          {"contacts", "Int32", 1, {s.contacts.begin(), s.contacts.end()}}};
}
}  // namespace

void write_snapshots(const OutputDir& out, const Recorder& rec) {
  remove_old_snapshots(out);
  std::vector<std::pair<double, std::string>> files;
  for (std::size_t k = 0; k < rec.snapshots.size(); ++k) {
    std::string name = fmt::format("snapshots/particles_{:04d}.vtp", k);
    const auto& snap = rec.snapshots[k].second;
    out.write(name, [&](std::ostream& o) { io::write_vtp(o, snap.position, point_data(snap)); });
    files.emplace_back(rec.snapshots[k].first, name);
  }
  if (!files.empty()) out.write("particles.pvd", [&](std::ostream& o) { io::write_pvd(o, files); });
}

namespace {

// The "breakage" object of result.json (impact/breakage.hpp); rebound keys for wall impacts only.
nlohmann::json breakage_json(const impact::Breakage& b) {
  nlohmann::json j = {{"fragment_primaries", b.fragment_sizes},   {"fragment_size_counts", b.size_counts},
                      {"largest_fragment_fraction", b.largest_fraction}, {"initial_contacts", b.initial_contacts},
                      {"broken_contacts", b.broken_contacts},       {"damage_ratio", b.damage_ratio},
                      {"rg_before_m", b.rg_before},                 {"rg_after_m", b.rg_after},
                      {"coordination_before", b.coordination_before}, {"coordination_after", b.coordination_after}};
  if (b.wall == impact::WallOutcome::none) return j;
  j["rebounded"] = b.wall == impact::WallOutcome::rebounded;
  j["rebound_kinetic_energy_J"] = b.rebound_kinetic;
  j["impact_kinetic_energy_J"] = b.impact_kinetic;
  j["rebound_energy_fraction"] = b.rebound_fraction;
  return j;
}

impact::Breakage breakage_from_json(const nlohmann::json& j) {
  impact::Breakage b;
  b.fragment_sizes = j.at("fragment_primaries").get<std::vector<int>>();
  b.size_counts = j.at("fragment_size_counts").get<std::vector<int>>();
  b.largest_fraction = j.at("largest_fragment_fraction").get<double>();
  b.initial_contacts = j.at("initial_contacts").get<int>();
  b.broken_contacts = j.at("broken_contacts").get<int>();
  b.damage_ratio = j.at("damage_ratio").get<double>();
  b.rg_before = j.at("rg_before_m").get<double>();
  b.rg_after = j.at("rg_after_m").get<double>();
  b.coordination_before = j.at("coordination_before").get<double>();
  b.coordination_after = j.at("coordination_after").get<double>();
  if (!j.contains("rebounded")) return b;
  b.wall = j.at("rebounded").get<bool>() ? impact::WallOutcome::rebounded : impact::WallOutcome::stuck;
  b.rebound_kinetic = j.at("rebound_kinetic_energy_J").get<double>();
  b.impact_kinetic = j.at("impact_kinetic_energy_J").get<double>();
  b.rebound_fraction = j.at("rebound_energy_fraction").get<double>();
  return b;
}

}  // namespace

nlohmann::json outcome_json(const ImpactOutcome& o) {
  nlohmann::json frags = nlohmann::json::array();
  for (const auto& f : o.fragments)
    frags.push_back({{"members", f.members},
                     {"escaping", f.escaping},
                     {"separation_rate_m_per_s", f.separation_rate},
                     {"relative_kinetic_energy_J", f.relative_ke},
                     {"electrostatic_binding_J", f.binding}});
  nlohmann::json j = {{"speed_m_per_s", o.speed},   {"broken", o.broken},          {"undecided", o.undecided},
          {"projectile_contact", o.contact}, {"components", o.components}, {"fragments", frags},
          {"t_first_contact_s", o.t_contact}, {"t_end_s", o.t_end},   {"dt_s", o.dt},
          {"steps", o.steps},           {"extensions", o.extensions}, {"early_stop", o.early_stop},
          {"electrostatic_solves", o.es_solves}, {"electrostatic_seconds", o.es_seconds}};
  // Error-controlled couplings only (electrostatics.force_tolerance > 0).
  if (o.es_hold_error.measured > 0)
    j["electrostatic_hold_error"] = {{"solves_measured", o.es_hold_error.measured},
                                     {"max_relative", o.es_hold_error.max},
                                     {"mean_relative", o.es_hold_error.mean},
                                     {"final_update_fraction", o.es_hold_error.fraction}};
  // Cases with a wall only (the others' result.json stays as it was).
  if (o.wall_contacts >= 0) j["wall_contacts_at_end"] = o.wall_contacts;
  if (o.contact) j["breakage"] = breakage_json(o.breakage);
  return j;
}

ImpactOutcome outcome_from_json(const nlohmann::json& j) {
  ImpactOutcome o;
  o.speed = j.at("speed_m_per_s").get<double>();
  o.broken = j.at("broken").get<bool>();
  o.undecided = j.at("undecided").get<bool>();
  o.contact = j.at("projectile_contact").get<bool>();
  o.components = j.at("components").get<std::vector<std::vector<int>>>();
  for (const auto& f : j.at("fragments"))
    o.fragments.push_back({f.at("members").get<std::vector<int>>(), f.at("escaping").get<bool>(),
                           f.at("separation_rate_m_per_s").get<double>(), f.at("relative_kinetic_energy_J").get<double>(),
                           f.at("electrostatic_binding_J").get<double>()});
  o.t_contact = j.at("t_first_contact_s").get<double>();
  o.t_end = j.at("t_end_s").get<double>();
  o.dt = j.at("dt_s").get<double>();
  o.steps = j.at("steps").get<long>();
  o.extensions = j.at("extensions").get<int>();
  o.early_stop = j.at("early_stop").get<bool>();
  o.es_solves = j.at("electrostatic_solves").get<long>();
  o.es_seconds = j.at("electrostatic_seconds").get<double>();
  if (j.contains("electrostatic_hold_error")) {
    const auto& h = j.at("electrostatic_hold_error");
    o.es_hold_error.measured = h.at("solves_measured").get<long>();
    o.es_hold_error.max = h.at("max_relative").get<double>();
    o.es_hold_error.mean = h.at("mean_relative").get<double>();
    o.es_hold_error.fraction = h.at("final_update_fraction").get<double>();
  }
  if (j.contains("wall_contacts_at_end")) o.wall_contacts = j.at("wall_contacts_at_end").get<int>();
  if (j.contains("breakage")) o.breakage = breakage_from_json(j.at("breakage"));
  return o;
}

nlohmann::json vcrit_json(const VcritResult& r) {
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& o : r.runs) {
    runs.push_back({{"v", o.speed}, {"broken", o.broken}, {"undecided", o.undecided}, {"contact", o.contact}});
    if (r.sticking) runs.back()["stuck"] = impact::stays(o);
  }
  nlohmann::json j = {{"v_crit", r.v_crit}, {"bracket", {r.lo, r.hi}}, {"rounds", r.rounds}, {"runs", runs},
                      {"warnings", r.warnings}};
  if (r.sticking) j["criterion"] = "sticking";  // (cases without vcrit.criterion keep their vcrit.json)
  return j;
}

namespace {

// The stratified rotations of an orientation-averaged break-up curve: impact direction in the
// agglomerate's frame and roll about the impact axis.
nlohmann::json orientations_json(int n) {
  nlohmann::json set = nlohmann::json::array();
  for (const auto& o : impact::stratified_orientations(n))
    set.push_back({{"direction", {o.direction.x, o.direction.y, o.direction.z}}, {"roll_rad", o.roll}});
  return set;
}

}  // namespace

io::Table breakup_table(const BreakupResult& r) {
  using P = impact::BreakupPoint;
  const auto& p = r.points;
  io::Table t("breakup.csv", {{"speed", p.size()}}, "{:.6g}");
  t.real("speed", "m s-1", "projectile speed (breakup.csv speed_m_s)", io::reals_of(p, [](const P& x) { return x.speed; }))
      .header({"speed_m_s"})
      .with_format("{:.9g}");
  t.integer("runs", "1", "runs at this speed", io::ints_of(p, [](const P& x) { return x.runs; }));
  t.integer("broken", "1", "runs that broke", io::ints_of(p, [](const P& x) { return x.broken; }));
  t.integer("undecided", "1", "runs undecided", io::ints_of(p, [](const P& x) { return x.undecided; }));
  t.real("p_break", "1", "break-up probability", io::reals_of(p, [](const P& x) { return x.p; }));
  t.real("ci95_lo", "1", "Wilson 95 % interval, lower end", io::reals_of(p, [](const P& x) { return x.ci_lo; }));
  t.real("ci95_hi", "1", "Wilson 95 % interval, upper end", io::reals_of(p, [](const P& x) { return x.ci_hi; }));
  t.real("damage_ratio", "1", "mean damage ratio of the runs", io::reals_of(p, [](const P& x) { return x.damage; }));
  t.real("damage_ratio_se", "1", "standard error of the mean damage ratio",
         io::reals_of(p, [](const P& x) { return x.damage_se; }));
  t.real("largest_fraction", "1", "mean largest-fragment fraction of the runs",
         io::reals_of(p, [](const P& x) { return x.largest; }));
  t.real("largest_fraction_se", "1", "standard error of the mean largest-fragment fraction",
         io::reals_of(p, [](const P& x) { return x.largest_se; }));
  return t;
}

void write_breakup(const OutputDir& out, const BreakupResult& r) {
  io::write_csv(out, breakup_table(r));
  auto level = [](double v) { return v < 0.0 ? nlohmann::json(nullptr) : nlohmann::json(v); };
  auto finite = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json pts = nlohmann::json::array(), runs = nlohmann::json::array();
  for (const auto& p : r.points)
    pts.push_back({{"speed", p.speed}, {"runs", p.runs}, {"broken", p.broken}, {"undecided", p.undecided},
                   {"p_break", p.p}, {"ci95", {p.ci_lo, p.ci_hi}}, {"damage_ratio", finite(p.damage)},
                   {"damage_ratio_se", finite(p.damage_se)}, {"largest_fraction", finite(p.largest)},
                   {"largest_fraction_se", finite(p.largest_se)}});
  const std::size_t m = r.offsets.size(), n = static_cast<std::size_t>(r.orientations);
  for (std::size_t j = 0; j < r.outcomes.size(); ++j) {
    const auto& o = r.outcomes[j];
    runs.push_back({{"v", o.speed}, {"offset_radii", r.offsets[j % m]}, {"broken", o.broken},
                    {"undecided", o.undecided}, {"contact", o.contact}});
    if (n > 1) runs.back()["orientation"] = (j / m) % n;
  }
  nlohmann::json doc{{"v10", level(r.v10)}, {"v50", level(r.v50)}, {"v90", level(r.v90)},
                     {"offsets_radii", r.offsets}, {"points", pts}, {"runs", runs}};
  if (n > 1) doc["orientations"] = orientations_json(r.orientations);
  out.write_json("breakup.json", doc);
}

}  // namespace agglo::writers
