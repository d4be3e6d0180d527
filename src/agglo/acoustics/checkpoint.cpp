#include "agglo/acoustics/checkpoint.hpp"

#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo::acoustics {

namespace {

// The layouts below list every field; a field added to one of these types must be added here too.
// 33 vectors and the flag carries_charge (padded to the vectors' alignment).
static_assert(sizeof(SampleSet) == 33 * sizeof(std::vector<double>) + alignof(std::vector<double>),
              "SampleSet changed: update each_array");
static_assert(sizeof(CellBounds) == 17 * sizeof(double), "CellBounds changed: update save_bounds");
static_assert(sizeof(BinnedGroup) == 2 * sizeof(std::vector<std::uint32_t>) + sizeof(CellBounds) + 8,
              "BinnedGroup changed: update save_groups");
static_assert(sizeof(BinnedGroups) == 11 * sizeof(std::vector<double>) + 5 * 8, "BinnedGroups changed: update save_groups");
// Written as raw bytes: these hold 8-byte numbers only (no padding).
static_assert(sizeof(CollisionStats) == 29 * 8, "CollisionStats changed: check it has no padding");
static_assert(sizeof(Counts) == 8 * 8 && sizeof(EfficiencyRow) == 20 * 8, "Counts changed: check it has no padding");

// Every array of a sample set, in a fixed order.
template <class S, class F>
void each_array(S& p, F&& f) {
  for (auto* v : {&p.x, &p.y, &p.z, &p.vx, &p.vy, &p.vz, &p.vol_s, &p.vol_l, &p.mass, &p.w, &p.debt, &p.debt_ref,
                  &p.d, &p.rho, &p.cc, &p.tau, &p.slip_l, &p.cphi, &p.sphi, &p.phase_code, &p.dl, &p.ccd, &p.acc_z,
                  &p.x_ref, &p.skx, &p.ckx})
    f(*v);
  f(p.pop);
  f(p.id);
  if (p.structured())  // aggregate structure (structure.hpp): set by the case, so save and load agree
    for (auto* v : {&p.np, &p.rp, &p.dm}) f(*v);
  if (p.carries_charge) f(p.q);  // charge (samples.hpp): set by the case, so save and load agree
}

template <class T>
void get(io::CheckpointReader& r, std::vector<T>& v) {
  v = r.pod_vector<T>();
}

template <class CB, class F>
void each_bound(CB& b, F&& f) {
  for (auto* x : {&b.d_max, &b.vol_max, &b.dl_max, &b.ccd_max, &b.speed_dev_max, &b.speed_dev2_max, &b.w_max,
                  &b.cbar_max, &b.mass_min, &b.d_min, &b.mass_max, &b.diff_max, &b.gap_max, &b.vref[0], &b.vref[1],
                  &b.vref[2]})
    f(*x);
}

void save_groups(const BinnedGroups& g, io::CheckpointWriter& w) {
  w.u64(g.groups.size());
  for (const BinnedGroup& b : g.groups) {
    w.pod_vector(b.members);
    w.pod_vector(b.ids);
    each_bound(b.cb, [&](double x) { w.f64(x); });
    w.boolean(b.cb.need_cbar);
    w.u64(b.key);
  }
  w.u64(g.count);
  w.pod_vector(g.size);
  w.pod_vector(g.version);
  w.pod_vector(g.group_of);
  w.pod_vector(g.pos_of);
  w.pod_vector(g.grouped);
  w.pod_vector(g.slots);
  w.u64(g.last_collisions);
  w.boolean(g.has_history);
  w.boolean(g.ids_valid);
  w.u64(g.clock);
  w.u64(g.cache_cap);
  w.pod_vector(g.cache_sum);
  w.pod_vector(g.cache_m);
  w.pod_vector(g.cache_va);
  w.pod_vector(g.cache_vb);
}

void load_groups(BinnedGroups& g, io::CheckpointReader& r) {
  g.groups.resize(r.u64());
  for (BinnedGroup& b : g.groups) {
    get(r, b.members);
    get(r, b.ids);
    each_bound(b.cb, [&](double& x) { x = r.f64(); });
    b.cb.need_cbar = r.boolean();
    b.key = static_cast<std::uint32_t>(r.u64());
  }
  g.count = r.u64();
  get(r, g.size);
  get(r, g.version);
  get(r, g.group_of);
  get(r, g.pos_of);
  get(r, g.grouped);
  get(r, g.slots);
  g.last_collisions = r.u64();
  g.has_history = r.boolean();
  g.ids_valid = r.boolean();
  g.clock = r.u64();
  g.cache_cap = r.u64();
  get(r, g.cache_sum);
  get(r, g.cache_m);
  get(r, g.cache_va);
  get(r, g.cache_vb);
}

void mismatch(const io::CheckpointReader& r, const char* what, std::size_t found, std::size_t want) {
  throw ConfigError(fmt::format("checkpoint {}: {} {} does not match this case's {}", r.file(), what, found, want));
}

}  // namespace

class EngineCheckpoint {
 public:
  static void save(const Engine& e, io::CheckpointWriter& w) {
    e.canonicalize();  // the samples in canonical order (engine.hpp), as a run that never sorted them
    w.u64(e.step_);
    each_array(e.p_, [&](const auto& v) { w.pod_vector(v); });
    w.pod(e.stats_);
    w.pod_vector(e.cell_of_);
    w.pod_vector(e.order_);
    w.pod_vector(e.start_);
    w.pod_vector(e.local_of_);
    w.boolean(e.regroup_);
    w.u64(e.groups_.size());
    for (const BinnedGroups& g : e.groups_) save_groups(g, w);
  }

  static void load(Engine& e, io::CheckpointReader& r) {
    const std::size_t n = e.p_.size();  // samples are never added or removed during a run
    e.forget_storage_order();            // the checkpoint holds the canonical order
    e.step_ = r.u64();
    each_array(e.p_, [&](auto& v) {
      get(r, v);
      if (v.size() != n) mismatch(r, "sample count", v.size(), n);
    });
    e.stats_ = r.pod<CollisionStats>();
    get(r, e.cell_of_);
    get(r, e.order_);
    get(r, e.start_);
    get(r, e.local_of_);
    const auto cells = static_cast<std::size_t>(e.s_.motion.domain.num_cells());
    if (e.start_.size() != cells + 1) mismatch(r, "cell count", e.start_.size() - 1, cells);
    if (e.cell_of_.size() != n || e.order_.size() != n) mismatch(r, "cell index length", e.order_.size(), n);
    e.regroup_ = r.boolean();
    e.groups_.resize(r.u64());
    for (BinnedGroups& g : e.groups_) load_groups(g, r);
  }
};

void save_engine(const Engine& e, io::CheckpointWriter& w) { EngineCheckpoint::save(e, w); }
void load_engine(Engine& e, io::CheckpointReader& r) { EngineCheckpoint::load(e, r); }

void save_observations(const AcousticObservations& o, io::CheckpointWriter& w) {
  w.pod_vector(o.efficiency);
  w.pod_vector(o.bins.edges);
  w.u64(o.psd.size());
  for (const PsdRecord& p : o.psd) {
    w.f64(p.t);
    for (const auto& v : p.dndlogd) w.pod_vector(v);
  }
  w.u64(o.snapshots.size());
  for (const SnapshotRow& s : o.snapshots) {
    for (double x : {s.t, s.x, s.y, s.z, s.d, s.vol_s, s.vol_l, s.w}) w.f64(x);
    w.u64(s.id);
    w.u64(static_cast<std::uint64_t>(s.phase));
  }
  w.pod(o.initial);
  w.f64(o.last_time_with_pure_droplets);
  w.str(o.log);
}

void load_observations(AcousticObservations& o, io::CheckpointReader& r) {
  get(r, o.efficiency);
  get(r, o.bins.edges);
  o.psd.resize(r.u64());
  for (PsdRecord& p : o.psd) {
    p.t = r.f64();
    for (auto& v : p.dndlogd) get(r, v);
  }
  o.snapshots.resize(r.u64());
  for (SnapshotRow& s : o.snapshots) {
    for (double* x : {&s.t, &s.x, &s.y, &s.z, &s.d, &s.vol_s, &s.vol_l, &s.w}) *x = r.f64();
    s.id = r.u64();
    s.phase = static_cast<Phase>(r.u64());
  }
  o.initial = r.pod<Counts>();
  o.last_time_with_pure_droplets = r.f64();
  o.log = r.str();
}

}  // namespace agglo::acoustics
