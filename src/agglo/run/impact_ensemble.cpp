#include "agglo/run/impact_ensemble.hpp"

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/io/impact_writers.hpp"

namespace agglo::run {

impact::ImpactBatch impact_batch(const impact::ImpactCase& c, const dem::Particles& relaxed, EnsembleOptions opt) {
  return [&c, &relaxed, opt](const std::vector<impact::ImpactJob>& batch) {
    std::vector<Job> jobs;
    for (const auto& b : batch) {
      jobs.push_back({fmt::format("v={:.17g} offset={:.17g}", b.speed, b.offset_radii),
                      [&c, &relaxed, b](const JobContext& ctx) {
                        auto ck = c;
                        ck.projectile.offset_radii = b.offset_radii;
                        auto poll = [&ctx](double, double) { throw_if_cancelled(ctx.cancel); };
                        return io::outcome_json(impact::run_impact(ck, b.speed, nullptr, poll, &relaxed));
                      }});
    }
    const auto outcomes = run_jobs(jobs, opt);
    rethrow_first_error(outcomes, &jobs);
    std::vector<impact::ImpactOutcome> out;
    for (const auto& o : outcomes) out.push_back(io::outcome_from_json(o.result));
    return out;
  };
}

impact::SpeedBatch speed_batch(const impact::ImpactCase& c, const dem::Particles& relaxed, EnsembleOptions opt) {
  return [run = impact_batch(c, relaxed, std::move(opt)), offset = c.projectile.offset_radii](
             const std::vector<double>& speeds) {
    std::vector<impact::ImpactJob> jobs;
    for (double v : speeds) jobs.push_back({v, offset});
    return run(jobs);
  };
}

std::string impact_context(std::string_view command, const Config& cfg) {
  return hash_hex(std::string(command) + "\n" + without_sections(cfg.resolved_toml(), {"vcrit", "breakup"}));
}

}  // namespace agglo::run
