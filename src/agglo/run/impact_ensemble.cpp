#include "agglo/run/impact_ensemble.hpp"

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/approach_cache.hpp"
#include "agglo/impact/orientation_set.hpp"
#include "agglo/writers/impact.hpp"

namespace agglo::run {

std::string impact_job_key(const impact::ImpactJob& b) {
  // The shortest digits that read back as the same double ("v=0.3", not "v=0.29999999999999999").
  std::string key = fmt::format("v={} offset={}", b.speed, b.offset_radii);
  if (b.orientations > 1) key += fmt::format(" orientation={}/{}", b.orientation, b.orientations);
  return key;
}

impact::ImpactBatch impact_batch(const impact::ImpactCase& c, const dem::Particles& relaxed, EnsembleOptions opt) {
  // One free flight before contact for every run from `relaxed` as oriented (impact/approach_cache.hpp).
  std::shared_ptr<impact::ApproachCache> approach;
  if (impact::ApproachCache::applies(c)) approach = std::make_shared<impact::ApproachCache>(c, relaxed);
  return [&c, &relaxed, opt, approach](const std::vector<impact::ImpactJob>& batch) {
    std::vector<Job> jobs;
    for (const auto& b : batch) {
      jobs.push_back({impact_job_key(b), [&c, &relaxed, b, approach](const JobContext& ctx) {
                        auto ck = c;
                        ck.projectile.offset_radii = b.offset_radii;
                        ck.time.bisection = b.bisection;
                        auto poll = [&ctx](double, double) { throw_if_cancelled(ctx.cancel); };
                        if (b.orientations <= 1)
                          return writers::outcome_json(
                              impact::run_impact(ck, b.speed, nullptr, poll, &relaxed, approach.get()));
                        // Rigid rotation of the relaxed agglomerate: contact overlaps and pair
                        // distances are unchanged, so it is still relaxed (no external field). An
                        // aggregate projectile takes a random orientation of its own for each.
                        if (ck.projectile.shape != "sphere")
                          ck.projectile.rotation = impact::projectile_orientation(ck, b.orientation);
                        dem::Particles turned = relaxed;
                        impact::rotate_about_centroid(
                            turned, impact::stratified_orientation(b.orientation, b.orientations).rotation);
                        return writers::outcome_json(impact::run_impact(ck, b.speed, nullptr, poll, &turned));
                      }});
    }
    const auto outcomes = run_jobs(jobs, opt);
    rethrow_first_error(outcomes, &jobs);
    std::vector<impact::ImpactOutcome> out;
    for (const auto& o : outcomes) out.push_back(writers::outcome_from_json(o.result));
    return out;
  };
}

impact::SpeedBatch speed_batch(const impact::ImpactCase& c, const dem::Particles& relaxed, EnsembleOptions opt) {
  // time.intact_stop = "vcrit" decides break-up only: a sticking bisection runs to full length.
  return [run = impact_batch(c, relaxed, std::move(opt)), offset = c.projectile.offset_radii,
          breakup = !c.vcrit.sticking](const std::vector<double>& speeds) {
    std::vector<impact::ImpactJob> jobs;
    for (double v : speeds) jobs.push_back({v, offset, 0, 1, breakup});
    return run(jobs);
  };
}

std::string impact_context(std::string_view command, const Config& cfg) {
  return hash_hex(std::string(command) + "\n" + without_sections(cfg.resolved_toml(), {"vcrit", "breakup"}));
}

}  // namespace agglo::run
