#include "agglo/io/acoustic_dataset.hpp"

#include <cmath>

#include "agglo/io/acoustic_writers.hpp"
#include "agglo/io/dataset_scalars.hpp"

namespace agglo::io {

namespace {

constexpr double kPerCm3 = 1e-6;  // 1/m^3 -> 1/cm^3, as in the CSV files
using acoustics::AcousticObservations;

void add_efficiency(Dataset& d, const AcousticObservations& o) {
  using R = acoustics::EfficiencyRow;
  const auto& e = o.efficiency;
  add_column(d, "time", "time", "s", "simulated time (efficiency.csv t_s)", reals_of(e, [](const R& r) { return r.t; }));
  d.add("n_total_cm3", {"time"}, "cm-3", "number concentration, all particles",
        reals_of(e, [](const R& r) { return r.counts.n_total * kPerCm3; }));
  const char* phases[3] = {"solid", "liquid", "mixed"};
  for (std::size_t k = 0; k < 3; ++k)
    d.add(std::string("n_") + phases[k] + "_cm3", {"time"}, "cm-3", std::string("number concentration, ") + phases[k],
          reals_of(e, [k](const R& r) { return r.counts.n_phase[k] * kPerCm3; }));
  d.add("fine_efficiency", {"time"}, "1", "agglomeration efficiency of the fine particles",
        reals_of(e, [](const R& r) { return r.fine_efficiency; }));
  d.add("pure_droplet_fraction", {"time"}, "1", "fraction of droplets still free of solid",
        reals_of(e, [](const R& r) { return r.pure_droplet_fraction; }));
  d.add("solid_volume_fraction", {"time"}, "1", "solid volume per box volume",
        reals_of(e, [](const R& r) { return r.counts.solid_volume; }));
  d.add("liquid_volume_fraction", {"time"}, "1", "liquid volume per box volume",
        reals_of(e, [](const R& r) { return r.counts.liquid_volume; }));
  d.add_ints("collisions", {"time"}, "1", "collisions so far", ints_of(e, [](const R& r) { return r.collisions; }));
  d.add_ints("subcycled_particle_steps", {"time"}, "1", "subcycled particle steps so far",
             ints_of(e, [](const R& r) { return r.subcycled; }));
}

void add_psd(Dataset& d, const AcousticObservations& o) {
  const auto& e = o.bins.edges;
  const std::size_t k = e.size() > 1 ? e.size() - 1 : 0;
  std::vector<double> lo, hi, mid;
  for (std::size_t b = 0; b < k; ++b) {
    lo.push_back(e[b]);
    hi.push_back(e[b + 1]);
    mid.push_back(std::sqrt(e[b] * e[b + 1]));
  }
  add_column(d, "psd_time", "psd_time", "s", "time of the size distribution",
             reals_of(o.psd, [](const auto& r) { return r.t; }));
  add_column(d, "diameter", "diameter", "m", "bin centre diameter (geometric mean of the edges, psd.csv d_mid_m)", mid);
  add_column(d, "diameter_edge", "diameter_edge", "m", "bin edge diameters", e);
  d.add("d_lo_m", {"diameter"}, "m", "lower bin edge", lo);
  d.add("d_hi_m", {"diameter"}, "m", "upper bin edge", hi);
  const char* names[4] = {"solid", "liquid", "mixed", "total"};
  for (std::size_t p = 0; p < 4; ++p) {
    std::vector<double> v;
    for (const auto& rec : o.psd)
      for (std::size_t b = 0; b < k; ++b) v.push_back(rec.dndlogd[p][b] * kPerCm3);
    d.add(std::string(names[p]) + "_dNdlogd_cm3", {"psd_time", "diameter"}, "cm-3",
          std::string("size distribution dN/dlog10(d), ") + names[p], v);
  }
}

void add_samples(Dataset& d, const AcousticObservations& o) {
  using S = acoustics::SnapshotRow;
  const auto& s = o.snapshots;
  const std::string dim = "snapshot_row";
  add_column(d, "snapshot_time", dim, "s", "time of the snapshot (snapshots.csv t_s)",
             reals_of(s, [](const S& r) { return r.t; }));
  d.add_ints("id", {dim}, "1", "sample id", ints_of(s, [](const S& r) { return r.id; }));
  d.add("x_m", {dim}, "m", "sample position x", reals_of(s, [](const S& r) { return r.x; }));
  d.add("y_m", {dim}, "m", "sample position y", reals_of(s, [](const S& r) { return r.y; }));
  d.add("z_m", {dim}, "m", "sample position z", reals_of(s, [](const S& r) { return r.z; }));
  d.add("d_m", {dim}, "m", "sample diameter", reals_of(s, [](const S& r) { return r.d; }));
  d.add("solid_volume_m3", {dim}, "m3", "solid volume of the particle", reals_of(s, [](const S& r) { return r.vol_s; }));
  d.add("liquid_volume_m3", {dim}, "m3", "liquid volume of the particle", reals_of(s, [](const S& r) { return r.vol_l; }));
  d.add("weight", {dim}, "1", "statistical weight (particles per sample)", reals_of(s, [](const S& r) { return r.w; }));
  d.add_ints("phase", {dim}, "1", "phase of the particle",
             ints_of(s, [](const S& r) { return static_cast<int>(r.phase); }))
      .attributes = {{"flag_values", {0, 1, 2}}, {"flag_meanings", "solid liquid mixed"}};
}

}  // namespace

Dataset acoustic_dataset(const AcousticObservations& o) {
  Dataset d;
  add_efficiency(d, o);
  add_psd(d, o);
  add_samples(d, o);
  if (!o.efficiency.empty()) add_scalars(d, acoustic_summary(o));  // the series' last values are already there
  return d;
}

}  // namespace agglo::io
