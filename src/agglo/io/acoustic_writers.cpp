#include "agglo/io/acoustic_writers.hpp"

#include <cmath>

#include <fmt/format.h>

namespace agglo::io {

namespace {
constexpr double kPerCm3 = 1e-6;  // 1/m^3 -> 1/cm^3
using acoustics::AcousticObservations;

nlohmann::json stats_json(const acoustics::CollisionStats& s, acoustics::Selection sel) {
  if (sel == acoustics::Selection::binned)
    return {{"particle_steps", s.particle_steps},
            {"candidates", s.trials},
            {"kernel_evals", s.kernel_evals},
            {"collisions", s.collisions},
            {"coalescences", {{"droplet", s.coalescences[0]}, {"dry", s.coalescences[1]}, {"wet", s.coalescences[2]}}},
            {"rebounds", {{"droplet", s.rebounds[0]}, {"dry", s.rebounds[1]}, {"wet", s.rebounds[2]}}},
            {"full_row_rate_computations", s.row_rate_updates},
            {"max_beta_over_majorant", s.max_pn},
            {"violations", s.violations},
            {"cell_steps_subdivided", s.subcycled},
            {"max_substeps", s.max_subcycles},
            {"refills", s.refills},
            {"dead_samples", s.dead},
            {"energy_lost_J", s.energy_lost},
            {"energy_returned_J", s.energy_returned}};
  return {{"particle_steps", s.particle_steps},
          {"trials", s.trials},
          {"kernel_evals", s.kernel_evals},
          {"collisions", s.collisions},
          {"coalescences", {{"droplet", s.coalescences[0]}, {"dry", s.coalescences[1]}, {"wet", s.coalescences[2]}}},
          {"rebounds", {{"droplet", s.rebounds[0]}, {"dry", s.rebounds[1]}, {"wet", s.rebounds[2]}}},
          {"max_bound_pn", s.max_bound_pn},
          {"subcycled_particle_steps", s.subcycled},
          {"max_subcycles", s.max_subcycles},
          {"max_pn_evaluated", s.max_pn},
          {"violations", s.violations},
          {"refills", s.refills},
          {"dead_samples", s.dead},
          {"energy_lost_J", s.energy_lost},
          {"energy_returned_J", s.energy_returned}};
}

void write_efficiency(std::ostream& os, const AcousticObservations& o) {
  os << "t_s,n_total_cm3,n_solid_cm3,n_liquid_cm3,n_mixed_cm3,fine_efficiency,pure_droplet_fraction,"
        "solid_volume_fraction,liquid_volume_fraction,collisions,subcycled_particle_steps\n";
  for (const auto& r : o.efficiency) {
    const auto& c = r.counts;
    os << fmt::format("{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.17g},{:.17g},{},{}\n", r.t,
                      c.n_total * kPerCm3, c.n_phase[0] * kPerCm3, c.n_phase[1] * kPerCm3, c.n_phase[2] * kPerCm3,
                      r.fine_efficiency, r.pure_droplet_fraction, c.solid_volume, c.liquid_volume, r.collisions,
                      r.subcycled);
  }
}

void write_psd(std::ostream& os, const AcousticObservations& o) {
  os << "t_s,d_lo_m,d_hi_m,d_mid_m,solid_dNdlogd_cm3,liquid_dNdlogd_cm3,mixed_dNdlogd_cm3,total_dNdlogd_cm3\n";
  const auto& e = o.bins.edges;
  for (const auto& rec : o.psd) {
    const auto& h = rec.dndlogd;
    for (std::size_t b = 0; b + 1 < e.size(); ++b)
      os << fmt::format("{:.8g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", rec.t, e[b], e[b + 1],
                        std::sqrt(e[b] * e[b + 1]), h[0][b] * kPerCm3, h[1][b] * kPerCm3, h[2][b] * kPerCm3,
                        h[3][b] * kPerCm3);
  }
}

void write_snapshots(std::ostream& os, const AcousticObservations& o) {
  os << "t_s,id,x_m,y_m,z_m,d_m,solid_volume_m3,liquid_volume_m3,weight,phase\n";
  for (const auto& s : o.snapshots)
    os << fmt::format("{:.8g},{},{:.8g},{:.8g},{:.8g},{:.6g},{:.6g},{:.6g},{:g},{}\n", s.t, s.id, s.x, s.y, s.z, s.d,
                      s.vol_s, s.vol_l, s.w, acoustics::phase_name(s.phase));
}

double rel_change(double a, double b) { return a > 0 ? b / a - 1 : 0.0; }
}  // namespace

nlohmann::json acoustic_summary(const AcousticObservations& o) {
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
          {o.selection == acoustics::Selection::binned ? "binned" : "nanbu", stats_json(o.stats, o.selection)},
          {"wall_time_s", o.wall_time_s}};
}

void write_acoustic(const OutputDir& out, const AcousticObservations& o, bool tables) {
  if (tables) {
    out.write("efficiency.csv", [&](std::ostream& os) { write_efficiency(os, o); });
    out.write("psd.csv", [&](std::ostream& os) { write_psd(os, o); });
    out.write("snapshots.csv", [&](std::ostream& os) { write_snapshots(os, o); });
  }
  out.write_text("run.log", o.log);
  if (tables) out.write_json("summary.json", acoustic_summary(o));
}

}  // namespace agglo::io
