#include "agglo/acoustics/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "agglo/acoustics/diagnostics.hpp"
#include "agglo/acoustics/engine.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/progress.hpp"

namespace agglo::acoustics {

namespace {
constexpr double kPerCm3 = 1e-6;  // 1/m^3 -> 1/cm^3

std::string guard_report(const NanbuStats& s) {
  return fmt::format(
      "nanbu: particle_steps={} trials={} kernel_evals={} collisions={} coalescences(droplet,dry,wet)=({},{},{}) "
      "rebounds(droplet,dry,wet)=({},{},{})\n"
      "nanbu guard: max N*P_bound(dt_c)={:.4g} subcycled_particle_steps={} ({:.3g}%) max_subcycles={} "
      "max N*P_ij evaluated={:.4g} violations(P_ij>1/N)={}\n"
      "nanbu refills={} dead_samples={} split_merge_energy_lost={:.6g} J compensated={:.6g} J\n",
      s.particle_steps, s.trials, s.kernel_evals, s.collisions, s.coalescences[0], s.coalescences[1], s.coalescences[2],
      s.rebounds[0], s.rebounds[1], s.rebounds[2], s.max_bound_pn, s.subcycled,
      s.particle_steps ? 100.0 * static_cast<double>(s.subcycled) / static_cast<double>(s.particle_steps) : 0.0,
      s.max_subcycles, s.max_pn, s.violations, s.refills, s.dead, s.energy_lost, s.energy_returned);
}

nlohmann::json stats_json(const NanbuStats& s) {
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

bool due(double t, double target, double dt) { return std::abs(t - target) < 0.5 * dt; }
}  // namespace

void check_startup(const AcousticCase& c, const Engine& e) {
  const auto& s = c.engine;
  const SampleSet& p = e.particles();
  if (s.motion.integrator == Integrator::explicit_euler) {
    double tmin = std::numeric_limits<double>::infinity();
    std::size_t imin = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.tau[i] < tmin) {
        tmin = p.tau[i];
        imin = i;
      }
    if (s.motion_dt >= 2.0 * tmin)
      throw ConfigError(fmt::format("{}: key 'time.motion_dt' = {:g}: the explicit integrator is unstable for "
                                    "motion_dt >= 2 tau; particle {} (d = {:.4g} m) has tau = {:.4g} s "
                                    "(use integrator = \"exact\" or a smaller step)",
                                    c.file, s.motion_dt, p.id[imin], p.d[imin], tmin));
  }
  const double pn = e.max_guard_pn();
  if (s.strict_guard && pn > 1.0)
    throw ConfigError(fmt::format("{}: key 'time.collision_dt' = {:g}: the Nanbu bound P_ij <= 1/N cannot be met "
                                  "(initial N P_bound = {:.4g}) and time.nanbu_guard = \"strict\"; reduce collision_dt "
                                  "by {:.3g}x or use nanbu_guard = \"subcycle\"",
                                  c.file, s.collision_dt, pn, pn));
  if (std::ceil(pn) > static_cast<double>(s.max_subcycles))
    throw ConfigError(fmt::format("{}: key 'time.max_subcycles' = {}: the Nanbu bound P_ij <= 1/N cannot be met: "
                                  "the initial state needs {:.4g} sub-cycles per collision step",
                                  c.file, s.max_subcycles, std::ceil(pn)));
}

nlohmann::json run_acoustic(Config& cfg, const OutputDir& out, const RunOptions& opt) {
  const auto wall0 = std::chrono::steady_clock::now();
  AcousticCase c = parse_acoustic_case(cfg);
  Engine eng(c.engine);
  check_startup(c, eng);
  const auto& S = eng.settings();
  const Motion& M = S.motion;
  const double V = M.domain.volume();

  std::ostringstream log;
  log << fmt::format("agglo acoustic: case {}\n", c.file);
  log << fmt::format("gas: T={:g} K P={:g} Pa rho_g={:.6g} kg/m^3 c={:.6g} m/s mu_g={:.6g} Pa s lambda_g={:.6g} m "
                     "gravity={:g} m/s^2\n",
                     M.gas.temperature, M.gas.pressure, M.gas.density, M.gas.sound_speed, M.gas.viscosity,
                     M.gas.mean_free_path, M.gas.gravity);
  log << fmt::format("sound: enabled={} L={:g} dB f={:g} Hz u_amp={:.6g} m/s wavelength={:.6g} m\n", M.sound.enabled,
                     M.sound.level_db, M.sound.frequency, M.sound.u_amp, M.sound.wavelength);
  log << fmt::format("domain: {:.6g} x {:.6g} x {:.6g} m, cells {}x{}x{}, V_c={:.6g} m^3\n", M.domain.L[0],
                     M.domain.L[1], M.domain.L[2], M.domain.cells[0], M.domain.cells[1], M.domain.cells[2],
                     M.domain.cell_volume());
  log << fmt::format("time: end={:g} s collision_dt={:g} s motion_dt={:g} s ({} motion sub-steps) integrator={} "
                     "kernel={}\n",
                     S.t_end, S.collision_dt, S.motion_dt, eng.motion_substeps(),
                     M.integrator == Integrator::exact ? "exact" : M.integrator == Integrator::none ? "none" : "explicit",
                     kernel_model_name(S.kernel.model));
  if (M.integrator == Integrator::exact && M.sound.u_amp > 0.0 && M.inertia_correction) {
    // C_I is held piecewise constant over a motion step. With an odd or fractional-but-locked number
    // of steps per acoustic period the sampled phases are not symmetric under psi -> psi + pi and a
    // droplet with C_I > 1 picks up a spurious mean drift (docs/acoustics.md sec. 3).
    const double per = 1.0 / (M.sound.frequency * S.motion_dt);
    const double even = 2.0 * std::round(0.5 * per);
    if (per < 40.0 && std::abs(per - even) > 1e-6 * per) {
      const std::string w = fmt::format(
          "warning: motion_dt = {:g} s gives {:.4g} steps per acoustic period; use an even whole number "
          "(e.g. motion_dt = {:g} s) to avoid a spurious drift of droplets with C_I > 1\n",
          S.motion_dt, per, 1.0 / (M.sound.frequency * std::max(2.0, even)));
      log << w;
      std::fputs(w.c_str(), stderr);
    }
  }
  for (std::size_t k = 0; k < eng.sampled().size(); ++k) {
    const auto& sp = eng.sampled()[k];
    log << fmt::format("population {} '{}': {} samples, requested N V = {:.6g}, sum of integer weights = {:.6g} "
                       "(rel. diff {:.3g})\n",
                       k, S.populations[k].name, sp.count, sp.real_number, sp.weight_sum,
                       sp.real_number > 0 ? sp.weight_sum / sp.real_number - 1.0 : 0.0);
    if (sp.real_number > 0 && std::abs(sp.weight_sum / sp.real_number - 1.0) > 0.01) {
      const std::string w = fmt::format(
          "warning: population {} '{}': the integer sample weights represent {:.4g} particles instead of {:.4g} "
          "({:+.2f} %); set weight_rounding = \"conserving\" or choose samples so that N V / samples is near a "
          "whole number\n",
          k, S.populations[k].name, sp.weight_sum, sp.real_number, 100.0 * (sp.weight_sum / sp.real_number - 1.0));
      log << w;
      std::fputs(w.c_str(), stderr);
    }
  }
  log << fmt::format("nanbu guard at start: max N*P_bound(dt_c) = {:.4g} ({})\n", eng.max_guard_pn(),
                     eng.max_guard_pn() > 1.0 ? "sub-cycling needed" : "bound met without sub-cycling");

  const Counts c0 = count(eng.particles(), V);
  const double nf0 = c0.n_phase[0], nl0 = c0.n_phase[1];
  const PsdBins bins = PsdBins::log_spaced(c.output.psd_d_min, c.output.psd_d_max, c.output.psd_bins);
  std::ostringstream eff, psdcsv, snap;
  eff << "t_s,n_total_cm3,n_solid_cm3,n_liquid_cm3,n_mixed_cm3,fine_efficiency,pure_droplet_fraction,"
         "solid_volume_fraction,liquid_volume_fraction,collisions,subcycled_particle_steps\n";
  psdcsv << "t_s,d_lo_m,d_hi_m,d_mid_m,solid_dNdlogd_cm3,liquid_dNdlogd_cm3,mixed_dNdlogd_cm3,total_dNdlogd_cm3\n";
  snap << "t_s,id,x_m,y_m,z_m,d_m,solid_volume_m3,liquid_volume_m3,weight,phase\n";
  double last_pure_t = nl0 > 0 ? 0.0 : -1.0;
  double eta = 0.0, pure = nl0 > 0 ? 1.0 : 0.0;
  auto record = [&](double t) {
    const Counts cc = count(eng.particles(), V);
    eta = nf0 > 0 ? (nf0 - cc.n_phase[0]) / nf0 : 0.0;
    pure = nl0 > 0 ? cc.n_phase[1] / nl0 : 0.0;
    if (cc.n_phase[1] > 0) last_pure_t = t;
    eff << fmt::format("{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.17g},{:.17g},{},{}\n", t,
                       cc.n_total * kPerCm3, cc.n_phase[0] * kPerCm3, cc.n_phase[1] * kPerCm3, cc.n_phase[2] * kPerCm3,
                       eta, pure, cc.solid_volume, cc.liquid_volume, eng.stats().collisions, eng.stats().subcycled);
  };
  auto record_psd = [&](double t) {
    const auto h = psd(eng.particles(), V, bins);
    for (std::size_t b = 0; b + 1 < bins.edges.size(); ++b)
      psdcsv << fmt::format("{:.8g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", t, bins.edges[b],
                            bins.edges[b + 1], std::sqrt(bins.edges[b] * bins.edges[b + 1]), h[0][b] * kPerCm3,
                            h[1][b] * kPerCm3, h[2][b] * kPerCm3, h[3][b] * kPerCm3);
  };
  auto record_snap = [&](double t) {
    const SampleSet& p = eng.particles();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.w[i] > 0 && p.x[i] <= c.output.snapshot_x_fraction * M.domain.L[0])
        snap << fmt::format("{:.8g},{},{:.8g},{:.8g},{:.8g},{:.6g},{:.6g},{:.6g},{:g},{}\n", t, p.id[i], p.x[i], p.y[i],
                            p.z[i], p.d[i], p.vol_s[i], p.vol_l[i], p.w[i], phase_name(p.phase(i)));
  };

  const std::uint64_t nsteps = eng.total_steps();
  const double dt = S.collision_dt;
  const std::uint64_t eff_every =
      std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(c.output.efficiency_interval / dt)));
  Progress prog(opt.label, opt.progress);
  auto outputs = [&](std::uint64_t s) {
    const double t = static_cast<double>(s) * dt;
    if (s % eff_every == 0 || s == nsteps) record(t);
    for (double tp : c.output.psd_times)
      if (due(t, tp, dt)) record_psd(t);
    for (double ts : c.output.snapshot_times)
      if (due(t, ts, dt)) record_snap(t);
  };
  outputs(0);
  for (std::uint64_t s = 1; s <= nsteps; ++s) {
    eng.step();
    outputs(s);
    if ((s & 63) == 0) prog.update(static_cast<double>(s) / static_cast<double>(nsteps), eng.time());
  }
  prog.finish();
  const Counts c1 = count(eng.particles(), V);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  log << guard_report(eng.stats());
  log << fmt::format("conservation: solid volume fraction {:.17g} -> {:.17g} (rel. {:.3g}); liquid {:.17g} -> {:.17g} "
                     "(rel. {:.3g}); mass {:.17g} -> {:.17g}\n",
                     c0.solid_volume, c1.solid_volume,
                     c0.solid_volume > 0 ? c1.solid_volume / c0.solid_volume - 1 : 0.0, c0.liquid_volume,
                     c1.liquid_volume, c0.liquid_volume > 0 ? c1.liquid_volume / c0.liquid_volume - 1 : 0.0, c0.mass,
                     c1.mass);
  log << fmt::format("result: fine_efficiency={:.6g} pure_droplet_fraction={:.6g} wall_time={:.3f} s\n", eta, pure, wall);

  nlohmann::json summary = {
      {"fine_efficiency", eta},
      {"pure_droplet_fraction", pure},
      {"last_time_with_pure_droplets_s", last_pure_t},
      {"n_solid_initial_cm3", nf0 * kPerCm3},
      {"n_solid_final_cm3", c1.n_phase[0] * kPerCm3},
      {"n_total_initial_cm3", c0.n_total * kPerCm3},
      {"n_total_final_cm3", c1.n_total * kPerCm3},
      {"samples", eng.particles().size()},
      {"steps", nsteps},
      {"u_amp_m_s", M.sound.u_amp},
      {"solid_volume_rel_change", c0.solid_volume > 0 ? c1.solid_volume / c0.solid_volume - 1 : 0.0},
      {"liquid_volume_rel_change", c0.liquid_volume > 0 ? c1.liquid_volume / c0.liquid_volume - 1 : 0.0},
      {"nanbu", stats_json(eng.stats())},
      {"wall_time_s", wall}};
  out.write_text("efficiency.csv", eff.str());
  out.write_text("psd.csv", psdcsv.str());
  out.write_text("snapshots.csv", snap.str());
  out.write_text("run.log", log.str());
  out.write_json("summary.json", summary);
  return summary;
}

}  // namespace agglo::acoustics
