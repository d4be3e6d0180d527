// Checkpoint payload of a collision run (impact/checkpoint.hpp).
#include "agglo/impact/checkpoint.hpp"

#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo::impact {

using io::CheckpointReader;
using io::CheckpointWriter;

namespace {

void write_particles(CheckpointWriter& w, const dem::Particles& p) {
  for (const auto* v : {&p.x, &p.v, &p.w, &p.f, &p.t}) w.pod_vector(*v);
  for (const auto* v : {&p.r, &p.m, &p.I, &p.q, &p.kappa}) w.pod_vector(*v);
  w.pod_vector(p.mat);
}

dem::Particles read_particles(CheckpointReader& r) {
  dem::Particles p;
  for (auto* v : {&p.x, &p.v, &p.w, &p.f, &p.t}) *v = r.pod_vector<Vec3>();
  for (auto* v : {&p.r, &p.m, &p.I, &p.q, &p.kappa}) *v = r.pod_vector<double>();
  p.mat = r.pod_vector<std::uint32_t>();
  return p;
}

void write_state(CheckpointWriter& w, const dem::ContactState& s) {
  w.boolean(s.active);
  w.f64(s.a);
  w.pod(s.xi_t);
  w.pod(s.xi_r);
  w.f64(s.xi_q);
  w.f64(s.delta);
}

dem::ContactState read_state(CheckpointReader& r) {
  dem::ContactState s;
  s.active = r.boolean();
  s.a = r.f64();
  s.xi_t = r.pod<Vec3>();
  s.xi_r = r.pod<Vec3>();
  s.xi_q = r.f64();
  s.delta = r.f64();
  return s;
}

void write_pairs(CheckpointWriter& w, const std::vector<dem::Pair>& pairs) {
  w.u64(pairs.size());
  for (const auto& pr : pairs) {
    w.u64(pr.i);
    w.u64(pr.j);
    write_state(w, pr.state);
    for (double c : {pr.jkr.R, pr.jkr.Estar, pr.jkr.gamma, pr.jkr.Fc, pr.jkr.a0, pr.jkr.deltaC}) w.f64(c);
  }
}

std::vector<dem::Pair> read_pairs(CheckpointReader& r) {
  std::vector<dem::Pair> pairs(r.u64());
  for (auto& pr : pairs) {
    pr.i = static_cast<std::uint32_t>(r.u64());
    pr.j = static_cast<std::uint32_t>(r.u64());
    pr.state = read_state(r);
    for (double* c : {&pr.jkr.R, &pr.jkr.Estar, &pr.jkr.gamma, &pr.jkr.Fc, &pr.jkr.a0, &pr.jkr.deltaC}) *c = r.f64();
    pr.jkr.derive();  // t_per_delta (not stored)
  }
  return pairs;
}

void write_dem(CheckpointWriter& w, const dem::DemState& s) {
  write_particles(w, s.particles);
  write_pairs(w, s.neighbors.pairs);
  w.pod_vector(s.neighbors.x_at_build);
  w.i64(s.neighbors.builds);
  for (double v : {s.dt, s.skin, s.time}) w.f64(v);
  w.i64(s.step);
  w.boolean(s.forces_ready);
  w.u64(s.walls.size());  // the wall contact states; their JKR constants are recomputed on restore
  for (const auto& wc : s.walls) {
    w.u64(wc.state.size());
    for (const auto& c : wc.state) write_state(w, c);
  }
}

dem::DemState read_dem(CheckpointReader& r) {
  dem::DemState s;
  s.particles = read_particles(r);
  s.neighbors.pairs = read_pairs(r);
  s.neighbors.x_at_build = r.pod_vector<Vec3>();
  s.neighbors.builds = r.i64();
  for (double* v : {&s.dt, &s.skin, &s.time}) *v = r.f64();
  s.step = r.i64();
  s.forces_ready = r.boolean();
  s.walls.resize(r.u64());
  for (auto& wc : s.walls) {
    wc.state.resize(r.u64());
    for (auto& c : wc.state) c = read_state(r);
  }
  return s;
}

void write_coupling(CheckpointWriter& w, const impact::CouplingState& s) {
  for (const auto* v : {&s.force, &s.torque, &s.x_at_solve, &s.n_s, &s.prev_force, &s.prev_torque}) w.pod_vector(*v);
  for (const auto* v : {&s.f_s, &s.u_s, &s.warm.values}) w.pod_vector(*v);
  w.pod_vector(s.visible);
  w.pod_vector(s.warm.ints);
  for (double v : {s.solution_energy, s.energy, s.prev_energy}) w.f64(v);
  for (long v : {s.step_at_solve, s.solves, s.step_at_prev, s.step_now}) w.i64(v);
  for (bool v : {s.correct, s.fast_path}) w.boolean(v);
  for (double v : {s.fraction, s.hold_error.max, s.hold_error.sum, s.hold_error.fraction}) w.f64(v);
  w.i64(s.hold_error.measured);
}

impact::CouplingState read_coupling(CheckpointReader& r) {
  impact::CouplingState s;
  for (auto* v : {&s.force, &s.torque, &s.x_at_solve, &s.n_s, &s.prev_force, &s.prev_torque}) *v = r.pod_vector<Vec3>();
  for (auto* v : {&s.f_s, &s.u_s, &s.warm.values}) *v = r.pod_vector<double>();
  s.visible = r.pod_vector<std::size_t>();
  s.warm.ints = r.pod_vector<long long>();
  for (double* v : {&s.solution_energy, &s.energy, &s.prev_energy}) *v = r.f64();
  for (long* v : {&s.step_at_solve, &s.solves, &s.step_at_prev, &s.step_now}) *v = r.i64();
  for (bool* v : {&s.correct, &s.fast_path}) *v = r.boolean();
  for (double* v : {&s.fraction, &s.hold_error.max, &s.hold_error.sum, &s.hold_error.fraction}) *v = r.f64();
  s.hold_error.measured = r.i64();
  return s;
}

void write_progress(CheckpointWriter& w, const impact::ImpactProgress& s) {
  w.i64(static_cast<std::int64_t>(s.phase));
  for (bool v : {s.contact, s.early_stop}) w.boolean(v);
  w.i64(s.extensions);
  for (double v : {s.t_contact, s.t_stop, s.t_from, s.t_launch, s.next_row, s.next_snap, s.e_launch, s.e_allowed})
    w.f64(v);
}

impact::ImpactProgress read_progress(CheckpointReader& r) {
  impact::ImpactProgress s;
  const auto phase = r.i64();
  if (phase < 0 || phase > static_cast<std::int64_t>(impact::ImpactPhase::done))
    throw ConfigError(fmt::format("checkpoint {}: invalid collision phase {}", r.file(), phase));
  s.phase = static_cast<impact::ImpactPhase>(phase);
  for (bool* v : {&s.contact, &s.early_stop}) *v = r.boolean();
  s.extensions = static_cast<int>(r.i64());
  for (double* v : {&s.t_contact, &s.t_stop, &s.t_from, &s.t_launch, &s.next_row, &s.next_snap, &s.e_launch,
                    &s.e_allowed})
    *v = r.f64();
  return s;
}

void write_recorder(CheckpointWriter& w, const impact::Recorder& rec) {
  w.u64(rec.rows.size());
  for (const auto& row : rec.rows) {
    for (double v : {row.t, row.kinetic, row.electrostatic, row.u_over_u0, row.rg, row.rg_agglomerate}) w.f64(v);
    w.i64(row.contacts);
  }
  w.u64(rec.snapshots.size());
  for (const auto& [t, s] : rec.snapshots) {
    w.f64(t);
    for (const auto* v : {&s.position, &s.velocity, &s.angular_velocity}) w.pod_vector(*v);
    w.pod_vector(s.radius);
    w.pod_vector(s.charge);
    w.pod_vector(s.contacts);
  }
}

impact::Recorder read_recorder(CheckpointReader& r) {
  impact::Recorder rec;
  rec.rows.resize(r.u64());
  for (auto& row : rec.rows) {
    for (double* v : {&row.t, &row.kinetic, &row.electrostatic, &row.u_over_u0, &row.rg, &row.rg_agglomerate})
      *v = r.f64();
    row.contacts = static_cast<int>(r.i64());
  }
  rec.snapshots.resize(r.u64());
  for (auto& [t, s] : rec.snapshots) {
    t = r.f64();
    for (auto* v : {&s.position, &s.velocity, &s.angular_velocity}) *v = r.pod_vector<Vec3>();
    s.radius = r.pod_vector<double>();
    s.charge = r.pod_vector<double>();
    s.contacts = r.pod_vector<int>();
  }
  return rec;
}

}  // namespace

void write_impact_state(CheckpointWriter& w, const impact::ImpactState& s) {
  w.u64(kImpactPayloadLayout);
  w.f64(s.speed);
  write_dem(w, s.dem);
  w.boolean(s.has_coupling);
  if (s.has_coupling) write_coupling(w, s.coupling);
  write_recorder(w, s.recorder);
  write_progress(w, s.progress);
  write_particles(w, s.launch);
}

impact::ImpactState read_impact_state(CheckpointReader& r) {
  const auto layout = r.u64();
  if (layout != kImpactPayloadLayout)
    throw ConfigError(fmt::format("checkpoint {}: collision payload layout {}, this build reads layout {}", r.file(),
                                  layout, kImpactPayloadLayout));
  impact::ImpactState s;
  s.speed = r.f64();
  s.dem = read_dem(r);
  s.has_coupling = r.boolean();
  if (s.has_coupling) s.coupling = read_coupling(r);
  s.recorder = read_recorder(r);
  s.progress = read_progress(r);
  s.launch = read_particles(r);
  r.expect_end();
  return s;
}

}  // namespace agglo::impact
