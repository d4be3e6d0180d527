#include "agglo/run/impact_ensemble.hpp"

#include <algorithm>
#include <memory>

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

namespace {

// The jobs of a batch of impacts (journal keys of impact_job_key), each from `relaxed`.
std::vector<Job> impact_jobs(const impact::ImpactCase& c, const dem::Particles& relaxed,
                             const std::shared_ptr<impact::ApproachCache>& approach,
                             const std::vector<impact::ImpactJob>& batch) {
  std::vector<Job> jobs;
  for (const auto& b : batch) {
    jobs.push_back({impact_job_key(b), [&c, &relaxed, b, approach](const JobContext& ctx) {
                      auto ck = c;
                      ck.projectile.offset_radii = b.offset_radii;
                      ck.time.bisection = b.bisection;
                      // A run no longer needed (an earlier job met the batch's stop rule) stops like a cancelled one.
                      auto poll = [&ctx](double, double) {
                        throw_if_cancelled(ctx.cancel);
                        if (ctx.superseded()) throw InterruptedError("superseded by an earlier job of the batch");
                      };
                      if (b.orientations <= 1)
                        return writers::outcome_json(
                            impact::run_impact(ck, b.speed, nullptr, poll, &relaxed, approach.get()));
                      // Rigid rotation of the relaxed agglomerate: contact overlaps and pair
                      // distances are unchanged, so it is still relaxed (no external field). An
                      // aggregate projectile takes a random orientation of its own for each.
                      if (ck.projectile.shape != "sphere")
                        ck.projectile.rotation = impact::projectile_orientation(ck, b.orientation);
                      dem::Particles turned = relaxed;
                      impact::rotate_about_centroid(turned,
                                                    impact::stratified_orientation(b.orientation, b.orientations).rotation);
                      return writers::outcome_json(impact::run_impact(ck, b.speed, nullptr, poll, &turned));
                    }});
  }
  return jobs;
}

// One free flight before contact for every run from `relaxed` as oriented (impact/approach_cache.hpp).
std::shared_ptr<impact::ApproachCache> approach_cache(const impact::ImpactCase& c, const dem::Particles& relaxed) {
  if (!impact::ApproachCache::applies(c)) return nullptr;
  return std::make_shared<impact::ApproachCache>(c, relaxed);
}

// The outcomes of the jobs up to the first whose result met opt.stop_after (run_jobs marks those after it
// skipped; all without a rule); the first error among them is rethrown.
std::vector<impact::ImpactOutcome> kept_outcomes(const std::vector<Job>& jobs, const EnsembleOptions& opt) {
  auto outcomes = run_jobs(jobs, opt);
  const auto end = std::find_if(outcomes.begin(), outcomes.end(), [](const JobOutcome& o) { return o.skipped; });
  outcomes.erase(end, outcomes.end());
  rethrow_first_error(outcomes, &jobs);
  std::vector<impact::ImpactOutcome> out;
  for (const auto& o : outcomes) out.push_back(writers::outcome_from_json(o.result));
  return out;
}

}  // namespace

impact::ImpactBatch impact_batch(const impact::ImpactCase& c, const dem::Particles& relaxed, EnsembleOptions opt) {
  return [&c, &relaxed, opt, approach = approach_cache(c, relaxed)](const std::vector<impact::ImpactJob>& batch) {
    return kept_outcomes(impact_jobs(c, relaxed, approach, batch), opt);
  };
}

impact::SpeedBatch speed_batch(const impact::ImpactCase& c, const dem::Particles& relaxed, EnsembleOptions opt) {
  // time.intact_stop = "vcrit" decides break-up only: a sticking bisection runs to full length.
  return [&c, &relaxed, opt, approach = approach_cache(c, relaxed)](const std::vector<double>& speeds,
                                                                    const impact::StopRule& stop) {
    std::vector<impact::ImpactJob> batch;
    for (double v : speeds) batch.push_back({v, c.projectile.offset_radii, 0, 1, !c.vcrit.sticking});
    EnsembleOptions o = opt;
    if (stop) o.stop_after = [&stop](const nlohmann::json& r) { return stop(writers::outcome_from_json(r)); };
    return kept_outcomes(impact_jobs(c, relaxed, approach, batch), o);
  };
}

std::string impact_context(std::string_view command, const Config& cfg) {
  return hash_hex(std::string(command) + "\n" + without_sections(cfg.resolved_toml(), {"vcrit", "breakup"}));
}

}  // namespace agglo::run
