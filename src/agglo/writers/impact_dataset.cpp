// results.nc of the impact commands (writers/impact.hpp).
#include <cmath>
#include <limits>

#include "agglo/io/dataset_scalars.hpp"
#include "agglo/writers/impact.hpp"

namespace agglo::writers {

using io::add_column;
using io::add_int_column;
using io::add_scalars;
using io::Dataset;
using io::ints_of;
using io::reals_of;

namespace {

const nlohmann::json kFlag = {{"flag_values", {0, 1}}, {"flag_meanings", "false true"}};

// Per-particle component and fragment index of an outcome (dim particle) and the fragment table.
void add_fragments(Dataset& d, const impact::ImpactOutcome& o) {
  std::size_t n = 0;
  for (const auto& c : o.components) n += c.size();
  d.add_dim("particle", n);
  std::vector<std::int64_t> component(n, -1), fragment(n, -1);
  for (std::size_t k = 0; k < o.components.size(); ++k)
    for (int i : o.components[k])
      if (i >= 0 && static_cast<std::size_t>(i) < n)
        component[static_cast<std::size_t>(i)] = static_cast<std::int64_t>(k);
  for (std::size_t k = 0; k < o.fragments.size(); ++k)
    for (int i : o.fragments[k].members)
      if (i >= 0 && static_cast<std::size_t>(i) < n)
        fragment[static_cast<std::size_t>(i)] = static_cast<std::int64_t>(k);
  d.add_ints("component", {"particle"}, "1", "contact-graph component at the end (projectile = last particle)",
             component);
  d.add_ints("particle_fragment", {"particle"}, "1", "fragment the particle belongs to (-1: none)", fragment);
  using F = impact::Fragment;
  const auto& fr = o.fragments;
  add_int_column(d, "fragment_size", "fragment", "1", "particles in the fragment",
                 ints_of(fr, [](const F& f) { return f.members.size(); }));
  d.add_ints("fragment_escaping", {"fragment"}, "1", "fragment escapes",
             ints_of(fr, [](const F& f) { return f.escaping; }))
      .attributes = kFlag;
  d.add("fragment_separation_rate_m_per_s", {"fragment"}, "m s-1", "rate of separation from the rest",
        reals_of(fr, [](const F& f) { return f.separation_rate; }));
  d.add("fragment_relative_kinetic_energy_J", {"fragment"}, "J", "kinetic energy relative to the rest",
        reals_of(fr, [](const F& f) { return f.relative_ke; }));
  d.add("fragment_electrostatic_binding_J", {"fragment"}, "J", "point-charge electrostatic binding to the rest",
        reals_of(fr, [](const F& f) { return f.binding; }));
}

std::vector<double> flatten(const std::vector<std::pair<double, dem::ParticleSnapshot>>& snaps,
                            std::vector<Vec3> dem::ParticleSnapshot::*field) {
  std::vector<double> out;
  for (const auto& s : snaps)
    for (const auto& v : s.second.*field) out.insert(out.end(), {v.x, v.y, v.z});
  return out;
}

std::vector<double> flatten(const std::vector<std::pair<double, dem::ParticleSnapshot>>& snaps,
                            std::vector<double> dem::ParticleSnapshot::*field) {
  std::vector<double> out;
  for (const auto& s : snaps) out.insert(out.end(), (s.second.*field).begin(), (s.second.*field).end());
  return out;
}

// The VTK snapshots as (frame, particle[, xyz]) arrays; skipped when the frames differ in particle count.
void add_snapshots(Dataset& d, const impact::Recorder& rec) {
  const auto& s = rec.snapshots;
  if (s.empty()) return;
  const std::size_t n = s.front().second.position.size();
  for (const auto& f : s)
    if (f.second.position.size() != n || f.second.radius.size() != n || f.second.charge.size() != n) return;
  for (const auto& [name, len] : d.dims)
    if (name == "particle" && len != n) return;
  d.add_dim("particle", n);
  d.add_dim("xyz", 3);
  add_column(d, "frame_time", "frame", "s", "time of the snapshot frame",
             reals_of(s, [](const auto& f) { return f.first; }));
  const nlohmann::json coord{{"coordinates", "frame_time"}};
  d.add("position", {"frame", "particle", "xyz"}, "m", "particle centre", flatten(s, &dem::ParticleSnapshot::position))
      .attributes = coord;
  d.add("velocity", {"frame", "particle", "xyz"}, "m s-1", "particle velocity", flatten(s, &dem::ParticleSnapshot::velocity))
      .attributes = coord;
  d.add("angular_velocity", {"frame", "particle", "xyz"}, "rad s-1", "particle angular velocity",
        flatten(s, &dem::ParticleSnapshot::angular_velocity))
      .attributes = coord;
  d.add("radius", {"frame", "particle"}, "m", "particle radius", flatten(s, &dem::ParticleSnapshot::radius)).attributes =
      coord;
  d.add("charge", {"frame", "particle"}, "C", "particle charge", flatten(s, &dem::ParticleSnapshot::charge)).attributes =
      coord;
  std::vector<std::int64_t> contacts;
  for (const auto& f : s) contacts.insert(contacts.end(), f.second.contacts.begin(), f.second.contacts.end());
  if (contacts.size() == s.size() * n)
    d.add_ints("contacts", {"frame", "particle"}, "1", "contacts of the particle", contacts).attributes = coord;
}

// The arrays of result.json's "breakage" (its scalars come with add_scalars): fragment sizes and their
// distribution over the coordinate breakage_size = 1 .. largest.
void add_breakage_arrays(Dataset& d, const impact::Breakage& b) {
  if (b.fragment_sizes.empty()) return;
  add_int_column(d, "breakage_fragment_primaries", "breakage_fragment", "1",
                 "agglomerate primaries in each fragment of the final contact graph, largest first",
                 ints_of(b.fragment_sizes, [](int k) { return k; }));
  std::vector<std::int64_t> size(b.size_counts.size());
  for (std::size_t k = 0; k < size.size(); ++k) size[k] = static_cast<std::int64_t>(k + 1);
  add_int_column(d, "breakage_size", "breakage_size", "1", "fragment size in primaries", size);
  d.add_ints("breakage_fragment_size_counts", {"breakage_size"}, "1", "fragments of this size",
             ints_of(b.size_counts, [](int k) { return k; }));
}

double level(double v) { return v < 0.0 ? std::numeric_limits<double>::quiet_NaN() : v; }

}  // namespace

Dataset collide_dataset(const impact::Recorder& rec, const impact::ImpactOutcome* outcome) {
  Dataset d;
  timeseries_table(rec).add_to(d);
  if (outcome) {
    add_scalars(d, outcome_json(*outcome));
    add_fragments(d, *outcome);
    add_breakage_arrays(d, outcome->breakage);
  }
  add_snapshots(d, rec);
  return d;
}

Dataset vcrit_dataset(const impact::VcritResult& r) {
  using O = impact::ImpactOutcome;
  Dataset d;
  add_column(d, "v", "run", "m s-1", "projectile speed of the run", reals_of(r.runs, [](const O& o) { return o.speed; }));
  d.add_ints("broken", {"run"}, "1", "the agglomerate broke", ints_of(r.runs, [](const O& o) { return o.broken; }))
      .attributes = kFlag;
  d.add_ints("undecided", {"run"}, "1", "outcome undecided", ints_of(r.runs, [](const O& o) { return o.undecided; }))
      .attributes = kFlag;
  d.add_ints("contact", {"run"}, "1", "the projectile touched the agglomerate",
             ints_of(r.runs, [](const O& o) { return o.contact; }))
      .attributes = kFlag;
  if (r.sticking) {  // vcrit.criterion = "sticking" (cases without it keep their results.nc)
    d.add_ints("stuck", {"run"}, "1", "the impact stayed (on the wall or the target)",
               ints_of(r.runs, [](const O& o) { return impact::stays(o); }))
        .attributes = kFlag;
    d.add("v_crit", {}, "m s-1", "sticking speed: largest speed that stays (lower end of the bracket)", {r.v_crit});
  } else {
    d.add("v_crit", {}, "m s-1", "critical break-up speed (upper end of the bracket)", {r.v_crit});
  }
  d.add("bracket_lo", {}, "m s-1", "lower end of the v_crit bracket", {r.lo});
  d.add("bracket_hi", {}, "m s-1", "upper end of the v_crit bracket", {r.hi});
  d.add_ints("rounds", {}, "1", "bisection rounds", {r.rounds});
  std::string warnings;
  for (const auto& w : r.warnings) warnings += (warnings.empty() ? "" : "\n") + w;
  if (!warnings.empty()) d.attributes["warnings"] = warnings;
  return d;
}

Dataset breakup_dataset(const impact::BreakupResult& r) {
  using O = impact::ImpactOutcome;
  Dataset d;
  breakup_table(r).add_to(d);
  add_column(d, "offsets_radii", "offset", "1", "lateral projectile offsets in projectile radii", r.offsets);
  const std::size_t m = std::max<std::size_t>(r.offsets.size(), 1),
                    n = static_cast<std::size_t>(std::max(r.orientations, 1));
  const auto& o = r.outcomes;
  add_column(d, "run_v", "run", "m s-1", "projectile speed of the run", reals_of(o, [](const O& x) { return x.speed; }));
  std::vector<double> offset;
  std::vector<std::int64_t> orientation;
  for (std::size_t j = 0; j < o.size(); ++j) {
    offset.push_back(r.offsets.empty() ? 0.0 : r.offsets[j % m]);
    orientation.push_back(static_cast<std::int64_t>((j / m) % n));
  }
  d.add("run_offset_radii", {"run"}, "1", "lateral offset of the run in projectile radii", offset);
  d.add_ints("run_broken", {"run"}, "1", "the run broke", ints_of(o, [](const O& x) { return x.broken; })).attributes =
      kFlag;
  d.add_ints("run_undecided", {"run"}, "1", "the run is undecided", ints_of(o, [](const O& x) { return x.undecided; }))
      .attributes = kFlag;
  d.add_ints("run_contact", {"run"}, "1", "the projectile touched", ints_of(o, [](const O& x) { return x.contact; }))
      .attributes = kFlag;
  if (n > 1) d.add_ints("run_orientation", {"run"}, "1", "orientation index of the run", orientation);
  d.add("v10", {}, "m s-1", "first speed with p_break >= 0.1 (NaN: not reached)", {level(r.v10)});
  d.add("v50", {}, "m s-1", "first speed with p_break >= 0.5 (NaN: not reached)", {level(r.v50)});
  d.add("v90", {}, "m s-1", "first speed with p_break >= 0.9 (NaN: not reached)", {level(r.v90)});
  return d;
}

}  // namespace agglo::writers
