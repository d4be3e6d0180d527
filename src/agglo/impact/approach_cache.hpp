#pragma once
// The free flight before the first contact, integrated once for every run of a case (issue 27: the
// seed-000 bisections). Until the projectile touches, nothing couples it to the agglomerate when
//  * it is one sphere without charge and with kappa_p = kappa_0 (outside the electrostatic solve:
//    electrostatic_coupling.hpp), and there is no gravity, gas drag or wall;
//  * its pairs are out of contact: a JKR pair adds exactly zero force until the overlap reaches 0
//    (dem/contact/pair_kernel.hpp, step 1), and it comes last in the pair order of every particle (it has
//    the highest index), so the agglomerate's force sums see the same operands in the same order.
// So after n steps the agglomerate is in the same state in every run of the case, whatever the speed
// or offset, and the projectile has drifted n times (x += dt v, v constant: it feels no force). The
// cache integrates the agglomerate alone and keeps its DEM and coupling states every kStride steps,
// with the largest displacement of any of its particles over the following kStride steps. A run then
// starts its approach from the latest kept state before which the projectile provably stayed clear of
// every particle (ImpactRun::skip_free_flight): bit for bit the state it would have reached step by step,
// but the projectile's pairs (out of contact, added to the neighbour list at its next rebuild).
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "agglo/dem/dem_state.hpp"
#include "agglo/impact/coupling_state.hpp"
#include "agglo/impact/impact_case.hpp"

namespace agglo::dem {
class DemSystem;
class ExternalForce;
}  // namespace agglo::dem

namespace agglo::impact {

class ApproachCache {
 public:
  static constexpr long kStride = 64;  // steps between kept states
  // Memory the kept states may take [bytes]: a large agglomerate with the spectral solver's warm start keeps
  // fewer (its runs then integrate the rest of their approach themselves).
  static constexpr double kBudget = 128.0 * 1024.0 * 1024.0;

  // The agglomerate after m kStride steps from the launch.
  struct Kept {
    dem::DemState dem;
    bool has_coupling = false;
    CouplingState coupling;
    double reach = 0.0;  // largest distance a particle moves from here over the next kStride steps [m]
  };

  // `c` and `agglomerate` (the launch state of the runs) must outlive the cache; `budget`: bytes of kept states.
  ApproachCache(const ImpactCase& c, const dem::Particles& agglomerate, double budget = kBudget);
  ~ApproachCache();
  ApproachCache(const ApproachCache&) = delete;
  ApproachCache& operator=(const ApproachCache&) = delete;

  // Whether runs of `c` can share their free flight (the conditions above that the case fixes; the
  // projectile's charge and permittivity are checked by the run).
  static bool applies(const ImpactCase& c);
  // Kept state m, integrating further when needed (thread-safe; the states do not depend on the order
  // in which runs ask for them); null beyond the memory budget.
  std::shared_ptr<const Kept> at(std::size_t m);

 private:
  void extend();  // integrates kStride more steps and keeps the state they started from

  const ImpactCase& c_;
  const dem::Particles& agglomerate_;
  std::mutex mutex_;
  std::unique_ptr<dem::ExternalForce> es_;
  std::unique_ptr<dem::DemSystem> sys_;
  std::vector<std::shared_ptr<const Kept>> kept_;
  double budget_;
  std::size_t limit_ = 0;  // kept states the budget allows (set by the first)
};

}  // namespace agglo::impact
